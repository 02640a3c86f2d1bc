package dev.predmon.report;

import dev.predmon.evaluate.RunResult;
import dev.predmon.parse.Clock;
import dev.predmon.property.Bound;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;

/**
 * One run's watched value (the battery level) over time from the start of the run, as a small SVG: the bound
 * dashed, the warning (dashed), the violation (solid) and the point where no model matched any more (dotted) as
 * vertical lines, the lead between warning and violation shaded. Where the run has a forecast, its probability of a
 * violation over the same time, as a step line on a scale of its own on the right (0 to 1), with the warning
 * threshold dotted across.
 *
 * <p>Each line's label has a row of its own above the plot, so that no two labels overlap however close their
 * lines, and is written on the side of its line that has room. The curve is thinned to what the plot can show:
 * per pixel column its first, lowest, highest and last point, then every point a straight line through its
 * neighbours already draws within half a pixel is left out. A battery that falls in steps or in a straight line
 * needs a few dozen points instead of thousands, which keeps a report of a hundred runs small.
 */
final class RunPlot {

    static final int WIDTH = 560;
    static final int HEIGHT = 254;
    private static final int RIGHT = 14;
    /** Room right of the plot for the probability's scale, when there is one. */
    private static final int RIGHT_WITH_P = 44;
    private static final int TOP = 46;
    private static final double ROW = 13;
    private static final double TOLERANCE = 0.5;

    private RunPlot() {
    }

    /** The plot of run {@code v}, whose values are {@code t}, for property {@code rule}. */
    static String svg(RunView v, Timeline t, Bound rule) {
        RunResult r = v.result();
        double start = r.start();
        Double warning = r.sinceStart(r.warningTime());
        Double violation = r.sinceStart(r.violationTime());
        Double noMatch = r.sinceStart(r.noMatchTime());
        double end = 0;
        double min = Math.min(0, rule.floor());
        double max = rule.floor();
        for (int i = 0; i < t.times().length; i++) {
            end = Math.max(end, t.times()[i] - start);
            min = Math.min(min, t.values()[i]);
            max = Math.max(max, t.values()[i]);
        }
        for (Double m : new Double[] {warning, violation, noMatch}) {
            end = m == null ? end : Math.max(end, m);
        }
        RunResult.ForecastTrace f = r.forecast();
        boolean p = f != null && !f.times().isEmpty();
        int right = p ? RIGHT_WITH_P : RIGHT;
        if (p) {
            for (double time : f.times()) {
                end = Math.max(end, time - start);
            }
        }
        boolean ticks = t.clock() == Clock.TICKS;
        Axis x = Axis.covering(0, end, 10, ticks, Axis.LEFT, WIDTH - right);
        Axis y = Axis.covering(min, max, 5, false, HEIGHT - Axis.BOTTOM, TOP);
        StringBuilder s = new StringBuilder(4096);
        s.append("<svg class=\"plot\" width=\"").append(WIDTH).append("\" height=\"").append(HEIGHT)
                .append("\" viewBox=\"0 0 ").append(WIDTH).append(' ').append(HEIGHT).append("\">");
        grid(s, x, y, right);
        if (warning != null && violation != null && warning < violation) {
            s.append("<rect class=\"lead\" x=\"").append(Svg.num(x.px(warning))).append("\" y=\"").append(TOP)
                    .append("\" width=\"").append(Svg.num(x.px(violation) - x.px(warning))).append("\" height=\"")
                    .append(HEIGHT - TOP - Axis.BOTTOM).append("\"/>");
        }
        s.append("<path class=\"bound\" d=\"M").append(Axis.LEFT).append(' ').append(Svg.num(y.px(rule.floor())))
                .append('H').append(WIDTH - right).append("\"/>");
        if (p) {
            probability(s, f, start, x);
        }
        if (t.times().length > 0) {
            s.append("<path class=\"val\" d=\"").append(path(t, start, x, y)).append("\"/>");
        } else {
            s.append(Svg.text("empty", (Axis.LEFT + WIDTH - right) / 2.0, (TOP + HEIGHT - Axis.BOTTOM) / 2.0,
                    "no reading of " + rule.value().command() + " in this run"));
        }
        marker(s, x, warning, "warn", 0, "warning " + v.duration(warning));
        marker(s, x, violation, "viol", 1, "violation " + v.duration(violation));
        marker(s, x, noMatch, "nomatch", 2, "no model matches from " + v.duration(noMatch));
        Axis.frame(s, x, y, "time (" + t.clock().unit() + " from start)", rule.value().command());
        return s.append("</svg>").toString();
    }

    private static void grid(StringBuilder s, Axis x, Axis y, int right) {
        s.append("<path class=\"grid\" d=\"");
        for (double tick : x.ticks()) {
            s.append('M').append(Svg.num(x.px(tick))).append(' ').append(TOP).append('V').append(HEIGHT - Axis.BOTTOM);
        }
        for (double tick : y.ticks()) {
            s.append('M').append(Axis.LEFT).append(' ').append(Svg.num(y.px(tick))).append('H').append(WIDTH - right);
        }
        s.append("\"/>");
    }

    /** The pixel height of probability {@code p} on the right-hand scale. */
    private static double py(double p) {
        return HEIGHT - Axis.BOTTOM - p * (HEIGHT - Axis.BOTTOM - TOP);
    }

    /**
     * The forecast's probability over the run as a step line (each forecast holds until the next), the threshold
     * dotted across, and the scale on the right: 0, 0.5 and 1, titled.
     */
    private static void probability(StringBuilder s, RunResult.ForecastTrace f, double start, Axis x) {
        double edge = x.to();
        if (f.threshold() >= 0 && f.threshold() <= 1) {
            s.append("<path class=\"pthr\" d=\"M").append(Axis.LEFT).append(' ').append(Svg.num(py(f.threshold())))
                    .append('H').append(Svg.num(edge)).append("\"/>");
        }
        List<double[]> steps = new ArrayList<>();
        for (int i = 0; i < f.times().size(); i++) {
            double px = x.px(f.times().get(i) - start);
            double level = py(f.probabilities().get(i));
            if (!steps.isEmpty()) {
                steps.add(new double[] {px, steps.get(steps.size() - 1)[1]});
            }
            steps.add(new double[] {px, level});
        }
        List<double[]> kept = simplified(steps);
        StringBuilder d = new StringBuilder(kept.size() * 10);
        for (int i = 0; i < kept.size(); i++) {
            d.append(i == 0 ? 'M' : 'L').append(Svg.num(kept.get(i)[0])).append(' ').append(Svg.num(kept.get(i)[1]));
        }
        s.append("<path class=\"prob\" d=\"").append(d).append("\"/>");
        s.append("<path class=\"axis\" d=\"M").append(Svg.num(edge)).append(' ').append(TOP).append('V')
                .append(HEIGHT - Axis.BOTTOM).append("\"/>");
        for (double tick : new double[] {0, 0.5, 1}) {
            s.append(Svg.text("tp", edge + 5, py(tick) + 3.5, tick == 0.5 ? "0.5" : tick == 0 ? "0" : "1"));
        }
        // rotated a quarter turn clockwise, the letters stand to the right of this line: it keeps them inside
        s.append("<text class=\"yp\" transform=\"translate(").append(WIDTH - 15).append(' ')
                .append(Svg.num((TOP + HEIGHT - Axis.BOTTOM) / 2.0)).append(") rotate(90)\">P(violation)</text>");
    }

    /**
     * A vertical line at {@code at} (time from start) of class {@code cls}, labelled in label row {@code row} on
     * its right, or on its left where the right has no room.
     */
    private static void marker(StringBuilder s, Axis x, Double at, String cls, int row, String label) {
        if (at == null) {
            return;
        }
        double px = x.px(at);
        s.append("<path class=\"").append(cls).append("\" d=\"M").append(Svg.num(px)).append(' ')
                .append(Svg.num(TOP - 4 - ROW * (2 - row))).append('V').append(HEIGHT - Axis.BOTTOM).append("\"/>");
        double w = Svg.width(label, true);
        boolean right = px + 4 + w <= WIDTH - 2;
        double baseline = 11 + ROW * row;
        s.append(Svg.text("m" + cls + (right ? "" : " end"), right ? px + 4 : Math.max(px - 4, w + 2), baseline, label));
    }

    /** The curve as path data, thinned to what the plot can show (see the class comment). */
    static String path(Timeline t, double start, Axis x, Axis y) {
        List<double[]> px = new ArrayList<>();
        int from = 0;
        while (from < t.times().length) {
            // One pixel column: its first, lowest, highest and last point, in the order they came.
            int column = (int) Math.floor(x.px(t.times()[from] - start));
            int to = from;
            int low = from;
            int high = from;
            while (to + 1 < t.times().length && (int) Math.floor(x.px(t.times()[to + 1] - start)) == column) {
                to++;
                low = t.values()[to] < t.values()[low] ? to : low;
                high = t.values()[to] > t.values()[high] ? to : high;
            }
            for (int i : new TreeSet<>(List.of(from, low, high, to))) {
                px.add(new double[] {x.px(t.times()[i] - start), y.px(t.values()[i])});
            }
            from = to + 1;
        }
        List<double[]> kept = simplified(px);
        StringBuilder d = new StringBuilder(kept.size() * 10);
        for (int i = 0; i < kept.size(); i++) {
            d.append(i == 0 ? 'M' : 'L').append(Svg.num(kept.get(i)[0])).append(' ').append(Svg.num(kept.get(i)[1]));
        }
        return d.toString();
    }

    /** Ramer-Douglas-Peucker: only the points more than {@link #TOLERANCE} pixels off the line that skips them. */
    static List<double[]> simplified(List<double[]> points) {
        if (points.size() < 3) {
            return points;
        }
        boolean[] keep = new boolean[points.size()];
        keep[0] = true;
        keep[points.size() - 1] = true;
        List<int[]> spans = new ArrayList<>();
        spans.add(new int[] {0, points.size() - 1});
        while (!spans.isEmpty()) {
            int[] span = spans.remove(spans.size() - 1);
            double[] a = points.get(span[0]);
            double[] b = points.get(span[1]);
            int far = -1;
            double farthest = TOLERANCE;
            for (int i = span[0] + 1; i < span[1]; i++) {
                double d = distance(points.get(i), a, b);
                if (d > farthest) {
                    farthest = d;
                    far = i;
                }
            }
            if (far >= 0) {
                keep[far] = true;
                spans.add(new int[] {span[0], far});
                spans.add(new int[] {far, span[1]});
            }
        }
        List<double[]> out = new ArrayList<>();
        for (int i = 0; i < points.size(); i++) {
            if (keep[i]) {
                out.add(points.get(i));
            }
        }
        return out;
    }

    private static double distance(double[] p, double[] a, double[] b) {
        double dx = b[0] - a[0];
        double dy = b[1] - a[1];
        double len = Math.hypot(dx, dy);
        if (len == 0) {
            return Math.hypot(p[0] - a[0], p[1] - a[1]);
        }
        return Math.abs(dy * (p[0] - a[0]) - dx * (p[1] - a[1])) / len;
    }
}
