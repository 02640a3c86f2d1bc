package dev.predmon.support;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import java.util.ArrayList;
import java.util.List;

/**
 * Which texts of a page's SVG drawings overlap on screen, as {@link HeadlessChromium} renders the page: every
 * {@code <details>} is opened, every non-empty {@code <text>} of every {@code <svg>} measured with
 * {@code getBoundingClientRect()} (the box the browser drew, after its own font metrics, {@code textLength} and
 * transforms), and each pair of boxes that share more than {@link #TOLERANCE} pixels each way is an overlap.
 */
public final class SvgTexts {

    /** Boxes that share less than this many pixels each way are not overlapping (anti-aliasing, rounding). */
    public static final double TOLERANCE = 0.5;

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String SCRIPT = """
            (() => {
              document.querySelectorAll('details').forEach(d => d.open = true);
              const tol = %s, out = [];
              let texts = 0, svgs = 0;
              document.querySelectorAll('svg').forEach((svg, i) => {
                const kind = (svg.getAttribute('class') || 'chart') + '#' + i;
                const boxes = [];
                svg.querySelectorAll('text').forEach(t => {
                  const r = t.getBoundingClientRect(), s = t.textContent.trim();
                  if (s && r.width > 0 && r.height > 0) boxes.push([s, r]);
                });
                svgs += svg.querySelector('text') ? 1 : 0;
                texts += boxes.length;
                for (let a = 0; a < boxes.length; a++) {
                  for (let b = a + 1; b < boxes.length; b++) {
                    const p = boxes[a][1], q = boxes[b][1];
                    if (p.left < q.right - tol && q.left < p.right - tol && p.top < q.bottom - tol && q.top < p.bottom - tol) {
                      out.push(kind + '\\t' + boxes[a][0] + '\\t' + boxes[b][0]);
                    }
                  }
                }
              });
              return JSON.stringify({svgs: svgs, texts: texts, overlaps: out});
            })()
            """.formatted(TOLERANCE);

    private SvgTexts() {
    }

    /**
     * What the browser measured.
     *
     * @param svgs     SVG elements on the page that hold text (drawings, not the shared definitions)
     * @param texts    non-empty texts measured in them
     * @param overlaps one {@code class#index, text, text} line per overlapping pair
     */
    public record Measured(int svgs, int texts, List<String> overlaps) {
    }

    /** Measures the page open in {@code page}, once it has loaded. */
    public static Measured measure(HeadlessChromium.Page page) throws Exception {
        loaded(page);
        JsonNode m = JSON.readTree(page.eval(SCRIPT));
        List<String> overlaps = new ArrayList<>();
        m.get("overlaps").forEach(o -> overlaps.add(o.asText()));
        return new Measured(m.get("svgs").asInt(), m.get("texts").asInt(), overlaps);
    }

    /** Waits until the page and everything in it has loaded (a tab is opened before its page has). */
    public static void loaded(HeadlessChromium.Page page) throws Exception {
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (!"true".equals(page.eval("String(location.href !== 'about:blank' && document.readyState === 'complete')"))) {
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("the page did not load within 60 s");
            }
            Thread.sleep(20);
        }
    }
}
