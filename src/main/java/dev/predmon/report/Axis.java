package dev.predmon.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A chart axis with round ticks: from {@code lo} to {@code hi} in steps of 1, 2 or 5 times a power of ten, the
 * ends on a tick, mapped onto pixels {@code from..to} (increasing or decreasing, as a y axis is).
 *
 * @param lo   the value at {@code from}, a multiple of {@code step}
 * @param hi   the value at {@code to}, a multiple of {@code step}
 * @param step the distance between two ticks
 * @param from the pixel of {@code lo}
 * @param to   the pixel of {@code hi}
 */
record Axis(double lo, double hi, double step, double from, double to) {

    /** Room left of a chart's y axis for its tick labels and title, in pixels. */
    static final int LEFT = 50;
    /** Room below a chart's x axis for its tick labels and title, in pixels ({@link #frame} fills it). */
    static final int BOTTOM = 42;

    /**
     * The axis that covers {@code min..max} with at most {@code maxTicks} steps; whole steps only when
     * {@code whole} (ticks or run counts).
     */
    static Axis covering(double min, double max, int maxTicks, boolean whole, double from, double to) {
        double range = max - min;
        if (!(range > 0)) {
            range = Math.max(1, Math.abs(max));
            max = min + range;
        }
        double step = roundStep(range / maxTicks);
        if (whole) {
            step = Math.max(1, step);
        }
        double lo = Math.floor(min / step + 1e-9) * step;
        double hi = Math.ceil(max / step - 1e-9) * step;
        return new Axis(lo, hi == lo ? lo + step : hi, step, from, to);
    }

    /** The smallest of 1, 2, 5, 10, 20, ... (or 0.5, 0.2, ...) at least {@code raw}. */
    static double roundStep(double raw) {
        if (!(raw > 0)) {
            return 1;
        }
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        for (double f : new double[] {1, 2, 5, 10}) {
            if (p * f >= raw - 1e-12) {
                return p * f;
            }
        }
        return p * 10;
    }

    /** The pixel of value {@code v}. */
    double px(double v) {
        return from + (v - lo) / (hi - lo) * (to - from);
    }

    /** The tick values, {@code lo} to {@code hi}. */
    List<Double> ticks() {
        List<Double> t = new ArrayList<>();
        int n = (int) Math.round((hi - lo) / step);
        for (int i = 0; i <= n; i++) {
            t.add(lo + i * step);
        }
        return t;
    }

    /** A tick's label: as many decimals as the step needs, none for a whole step. */
    String label(double v) {
        int decimals = step >= 1 ? 0 : (int) Math.ceil(-Math.log10(step) - 1e-9);
        return String.format(Locale.ROOT, "%." + decimals + "f", Math.abs(v) < step / 1e6 ? 0.0 : v);
    }

    /**
     * The axes' lines, tick labels and titles of a chart whose x axis is {@code x} and y axis {@code y}. The tick
     * labels are placed so that the y axis's lowest and the x axis's first never touch where the axes meet: a
     * y label is centred on its tick and the x labels hang a full line below the axis.
     */
    static void frame(StringBuilder s, Axis x, Axis y, String xTitle, String yTitle) {
        double bottom = y.from();
        double left = x.from();
        s.append("<path class=\"axis\" d=\"M").append(Svg.num(left)).append(' ').append(Svg.num(y.to())).append('V')
                .append(Svg.num(bottom)).append('H').append(Svg.num(x.to())).append("\"/>");
        for (double tick : x.ticks()) {
            s.append(Svg.text("tx", x.px(tick), bottom + 18, x.label(tick)));
        }
        for (double tick : y.ticks()) {
            s.append(Svg.text("ty", left - 6, y.px(tick) + 3.5, y.label(tick)));
        }
        s.append(Svg.text("xl", (left + x.to()) / 2, bottom + 35, xTitle));
        s.append("<text class=\"yl\" transform=\"translate(13 ").append(Svg.num((y.from() + y.to()) / 2))
                .append(") rotate(-90)\">").append(Svg.esc(yTitle)).append("</text>");
    }
}
