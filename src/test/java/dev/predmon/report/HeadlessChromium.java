package dev.predmon.report;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Renders an HTML page in headless Chromium and reports which texts of its SVG drawings overlap on screen. A
 * script added at the end of the page opens every {@code <details>}, measures every non-empty
 * {@code <text>} of every {@code <svg>} with {@code getBoundingClientRect()} (the box the browser drew, after its
 * own font metrics, {@code textLength} and transforms), and writes each overlapping pair into the DOM, which
 * {@code --dump-dom} prints. No Selenium, no driver: the browser binary alone.
 */
final class HeadlessChromium {

    /** Boxes that share less than this many pixels each way are not overlapping (anti-aliasing, rounding). */
    static final double TOLERANCE = 0.5;

    private static final String SCRIPT = """
            <script>
            (function () {
              document.querySelectorAll('details').forEach(d => d.open = true);
              const tol = %s, out = [];
              let texts = 0;
              document.querySelectorAll('svg').forEach((svg, i) => {
                const kind = (svg.getAttribute('class') || 'chart') + '#' + i;
                const boxes = [];
                svg.querySelectorAll('text').forEach(t => {
                  const r = t.getBoundingClientRect(), s = t.textContent.trim();
                  if (s && r.width > 0 && r.height > 0) boxes.push([s, r]);
                });
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
              const pre = document.createElement('pre');
              pre.id = 'predmon-overlaps';
              pre.setAttribute('data-texts', texts);
              pre.setAttribute('data-svgs', document.querySelectorAll('svg').length);
              pre.textContent = out.join('\\n');
              document.body.appendChild(pre);
            })();
            </script>
            """.formatted(TOLERANCE);
    private static final Pattern RESULT = Pattern.compile(
            "<pre id=\"predmon-overlaps\" data-texts=\"(\\d+)\" data-svgs=\"(\\d+)\">(.*?)</pre>", Pattern.DOTALL);

    private HeadlessChromium() {
    }

    /**
     * What the browser measured.
     *
     * @param svgs     SVG elements on the page
     * @param texts    non-empty texts measured in them
     * @param overlaps one {@code class#index, text, text} line per overlapping pair
     */
    record Measured(int svgs, int texts, List<String> overlaps) {
    }

    /** The {@code chromium} or {@code chromium-browser} on the PATH, if any. */
    static Optional<Path> find() {
        String path = System.getenv("PATH");
        if (path == null) {
            return Optional.empty();
        }
        for (String name : List.of("chromium", "chromium-browser")) {
            for (String dir : path.split(File.pathSeparator)) {
                Path p = Path.of(dir.isEmpty() ? "." : dir, name);
                if (Files.isExecutable(p)) {
                    return Optional.of(p);
                }
            }
        }
        return Optional.empty();
    }

    /** Renders {@code html} with {@code chromium} (window 1400 px wide) and measures its SVG texts. */
    static Measured measure(Path chromium, String html, Path work) throws IOException, InterruptedException {
        int end = html.lastIndexOf("</body>");
        String page = end < 0 ? html + SCRIPT : html.substring(0, end) + SCRIPT + html.substring(end);
        Path file = Files.writeString(work.resolve("page.html"), page, StandardCharsets.UTF_8);
        Path profile = Files.createDirectories(work.resolve("profile"));
        Process p = new ProcessBuilder(chromium.toString(), "--headless", "--no-sandbox", "--disable-gpu",
                "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--user-data-dir=" + profile, "--window-size=1400,1000", "--dump-dom",
                file.toUri().toString())
                .redirectError(ProcessBuilder.Redirect.DISCARD).start();
        String dom;
        try {
            dom = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            if (!p.waitFor(120, TimeUnit.SECONDS)) {
                throw new IllegalStateException("chromium did not exit within 120 s");
            }
        } finally {
            p.destroyForcibly();
            deleteTree(profile);
        }
        Matcher m = RESULT.matcher(dom);
        if (!m.find()) {
            throw new IllegalStateException("chromium (exit " + p.exitValue() + ") printed no measurement; DOM starts: "
                    + dom.substring(0, Math.min(300, dom.length())));
        }
        List<String> overlaps = new ArrayList<>();
        for (String line : m.group(3).split("\n")) {
            if (!line.isBlank()) {
                overlaps.add(unescape(line));
            }
        }
        return new Measured(Integer.parseInt(m.group(2)), Integer.parseInt(m.group(1)), overlaps);
    }

    private static String unescape(String s) {
        return s.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"").replace("&amp;", "&");
    }

    private static void deleteTree(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path q : s.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(q);
            }
        }
    }
}
