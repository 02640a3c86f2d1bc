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
}
