package dev.predmon.evaluate;

import dev.predmon.mealy.MealyMapping;
import dev.predmon.model.LearnedModel;
import net.automatalib.automaton.transducer.CompactMealy;
import org.jfree.svg.SVGGraphics2D;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.QuadCurve2D;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Draws a learned Mealy machine as SVG without Graphviz: states in layers by breadth-first distance from the
 * initial state (left to right, in the deterministic order of the alphabet), one arrow per pair of states with
 * all its {@code input/output} labels stacked, self-loops as small arcs above the state, edges to an earlier or
 * the same layer bent. Deterministic: the same machine always gives the same picture.
 *
 * <p>The thesis's mapping turns each query/reply pair into two Mealy steps, {@code input/OK} into a state that
 * only waits for {@code Delta/reply}. Such waiting states are folded away: the pair is drawn as one edge
 * {@code input / reply} between the states that matter, which halves the picture and reads like the I/O
 * automaton the machine stands for. A state that does more than wait is drawn, with its own edges.
 */
public final class MachineDrawing {

    private static final int COL = 190;
    private static final int ROW = 90;
    private static final int R = 16;
    private static final Font FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 10);

    private MachineDrawing() {
    }

    /** The machine as an inline {@code <svg>} element; {@code key} keeps element ids unique within a page. */
    public static String svg(LearnedModel model, String key) {
        CompactMealy<String, String> m = model.machine();
        // Only symbols of the machine's own alphabet have transitions (as ModelTracker checks too).
        List<String> inputs = new ArrayList<>(model.alphabet().stream().filter(m.getInputAlphabet()::containsSymbol).toList());
        Map<Integer, Integer> layer = new LinkedHashMap<>();
        Deque<Integer> queue = new ArrayDeque<>();
        Integer init = m.getInitialState();
        if (init == null) {
            return "<p>(empty machine)</p>";
        }
        layer.put(init, 0);
        queue.add(init);
        while (!queue.isEmpty()) {
            Integer s = queue.poll();
            for (Edge e : edges(m, inputs, s)) {
                if (!layer.containsKey(e.target())) {
                    layer.put(e.target(), layer.get(s) + 1);
                    queue.add(e.target());
                }
            }
        }
        // Labels per (source, target), in alphabet order.
        Map<Long, List<String>> labels = new LinkedHashMap<>();
        for (Integer s : layer.keySet()) {
            for (Edge e : edges(m, inputs, s)) {
                labels.computeIfAbsent(((long) s << 32) | e.target().longValue(), k -> new ArrayList<>()).add(e.label());
            }
        }
        // Spacing from the labels themselves, so that long symbols and tall stacks neither overlap nor get cut.
        FontMetrics fm = new SVGGraphics2D(10, 10).getFontMetrics(FONT);
        int widest = labels.values().stream().flatMap(List::stream).mapToInt(fm::stringWidth).max().orElse(0);
        int tallest = labels.values().stream().mapToInt(List::size).max().orElse(1) * fm.getHeight();
        int col = Math.max(COL, widest + 60);
        int rowHeight = Math.max(ROW, tallest + 2 * R + 30);
        int left = widest / 2 + 20;
        int top = tallest + R + 40;
        Map<Integer, double[]> pos = new LinkedHashMap<>();
        Map<Integer, Integer> perLayer = new LinkedHashMap<>();
        for (Map.Entry<Integer, Integer> e : layer.entrySet()) {
            int row = perLayer.merge(e.getValue(), 1, Integer::sum) - 1;
            pos.put(e.getKey(), new double[] {left + e.getValue() * col, top + row * rowHeight});
        }
        int layers = perLayer.size();
        int rows = perLayer.values().stream().mapToInt(Integer::intValue).max().orElse(1);
        int width = 2 * left + Math.max(0, layers - 1) * col;
        int height = top + Math.max(0, rows - 1) * rowHeight + tallest + R + 60;
        SVGGraphics2D g = new SVGGraphics2D(width, height);
        g.setDefsKeyPrefix(key);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setFont(FONT);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, width, height);
        for (Map.Entry<Long, List<String>> e : labels.entrySet()) {
            int s = (int) (e.getKey() >>> 32);
            int t = (int) (long) e.getKey();
            double[] a = pos.get(s);
            double[] b = pos.get(t);
            g.setColor(new Color(80, 80, 80));
            g.setStroke(new BasicStroke(1f));
            double lx;
            double ly;
            if (s == t) {
                g.draw(new Ellipse2D.Double(a[0] - 10, a[1] - R - 18, 20, 22));
                lx = a[0];
                ly = a[1] - R - 22 - (e.getValue().size() - 1) * fm.getHeight();
            } else {
                boolean backward = layer.get(t) <= layer.get(s);
                double mx = (a[0] + b[0]) / 2;
                double my = (a[1] + b[1]) / 2 + (backward ? 28 + 10 * Math.abs(layer.get(s) - layer.get(t)) : 0);
                double[] from = border(a, mx, my);
                double[] to = border(b, mx, my);
                g.draw(new QuadCurve2D.Double(from[0], from[1], mx, my, to[0], to[1]));
                arrowHead(g, mx, my, to);
                lx = backward ? mx : (from[0] + to[0]) / 2 * 0.5 + mx * 0.5;
                ly = backward ? my + 4 : my - 4 - (e.getValue().size() - 1) * fm.getHeight();
            }
            g.setColor(new Color(20, 60, 140));
            for (int i = 0; i < e.getValue().size(); i++) {
                String text = e.getValue().get(i);
                g.drawString(text, (float) (lx - fm.stringWidth(text) / 2.0), (float) (ly + i * fm.getHeight()));
            }
        }
        for (Map.Entry<Integer, double[]> e : pos.entrySet()) {
            double[] p = e.getValue();
            g.setColor(e.getKey().equals(init) ? new Color(220, 235, 255) : new Color(245, 245, 245));
            g.fill(new Ellipse2D.Double(p[0] - R, p[1] - R, 2 * R, 2 * R));
            g.setColor(Color.BLACK);
            g.setStroke(new BasicStroke(e.getKey().equals(init) ? 2f : 1f));
            g.draw(new Ellipse2D.Double(p[0] - R, p[1] - R, 2 * R, 2 * R));
            String name = "s" + e.getKey();
            g.drawString(name, (float) (p[0] - fm.stringWidth(name) / 2.0), (float) (p[1] + fm.getAscent() / 2.0 - 1));
        }
        return g.getSVGElement(key);
    }

    /** One drawn edge. */
    private record Edge(Integer target, String label) {
    }

    /**
     * The edges drawn from {@code s}: a query whose successor only waits for {@code Delta} becomes one edge
     * {@code input / reply} to where the reply leads; any other transition is drawn as it is.
     */
    private static List<Edge> edges(CompactMealy<String, String> m, List<String> inputs, Integer s) {
        List<Edge> out = new ArrayList<>();
        for (String in : inputs) {
            // Boxed on purpose: the int overload of getSuccessor answers -1, not null, for a missing transition.
            Integer t = m.getSuccessor(s, in);
            if (t == null) {
                continue;
            }
            String answer = m.getOutput(s, in);
            if (!in.equals(MealyMapping.DELTA) && MealyMapping.OK.equals(answer) && onlyWaits(m, inputs, t)) {
                out.add(new Edge(m.getSuccessor(t, MealyMapping.DELTA), in + " / " + m.getOutput(t, MealyMapping.DELTA)));
            } else {
                out.add(new Edge(t, MealyMapping.OK.equals(answer) ? in : in + " / " + answer));
            }
        }
        return out;
    }

    /** Whether {@code t}'s only transition is {@code Delta}: the state between a query and its reply. */
    private static boolean onlyWaits(CompactMealy<String, String> m, List<String> inputs, Integer t) {
        for (String in : inputs) {
            if (m.getSuccessor(t, in) != null && !in.equals(MealyMapping.DELTA)) {
                return false;
            }
        }
        return m.getSuccessor(t, MealyMapping.DELTA) != null;
    }

    /** Where the line from the centre {@code c} towards {@code (x, y)} leaves the state's circle. */
    private static double[] border(double[] c, double x, double y) {
        double dx = x - c[0];
        double dy = y - c[1];
        double d = Math.max(1e-9, Math.hypot(dx, dy));
        return new double[] {c[0] + dx / d * R, c[1] + dy / d * R};
    }

    private static void arrowHead(SVGGraphics2D g, double fromX, double fromY, double[] tip) {
        double angle = Math.atan2(tip[1] - fromY, tip[0] - fromX);
        Path2D head = new Path2D.Double();
        head.moveTo(tip[0], tip[1]);
        head.lineTo(tip[0] - 8 * Math.cos(angle - 0.4), tip[1] - 8 * Math.sin(angle - 0.4));
        head.lineTo(tip[0] - 8 * Math.cos(angle + 0.4), tip[1] - 8 * Math.sin(angle + 0.4));
        head.closePath();
        g.fill(head);
    }
}
