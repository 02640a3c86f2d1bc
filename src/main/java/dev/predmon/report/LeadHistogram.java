package dev.predmon.report;

import dev.predmon.parse.Clock;

import java.util.Arrays;

/**
 * The distribution of leads as a small SVG histogram: bins of a round width (1, 2 or 5 times a power of ten)
 * starting at a multiple of it, at most {@value #MAX_BINS}, whole numbers of runs on the vertical axis, and at
 * least {@value #MIN_BINS} bins wide so that a single lead is a bar, not the whole plot.
 */
final class LeadHistogram {

    static final int WIDTH = 700;
    static final int HEIGHT = 280;
    private static final int RIGHT = 16;
    private static final int TOP = 12;
    private static final int MAX_BINS = 20;
    private static final int MIN_BINS = 8;

    private LeadHistogram() {
    }

    /** The histogram of {@code leads}, counted in {@code clock}'s unit. */
    static String svg(double[] leads, Clock clock) {
        double min = Arrays.stream(leads).min().orElse(0);
        double max = Arrays.stream(leads).max().orElse(0);
        double width = binWidth(max - min);
        double from = Math.floor(min / width) * width;
        int bins = Math.max(1, (int) Math.ceil((max - from) / width - 1e-9));
        if (from + bins * width <= max) {
            bins++; // max on a bin's edge: the last bin is [edge, edge + width)
        }
        int[] counts = new int[bins];
        for (double l : leads) {
            counts[Math.min(bins - 1, (int) Math.floor((l - from) / width + 1e-9))]++;
        }
        int pad = Math.max(0, MIN_BINS - bins);
        int padLeft = pad / 2; // whole bins: the left gets the smaller half of an odd padding
        double lower = Math.max(Math.min(0, from), from - padLeft * width);
        double upper = Math.max(lower + MIN_BINS * width, from + bins * width);
        Axis x = Axis.covering(lower, upper, 10, clock == Clock.TICKS, Axis.LEFT, WIDTH - RIGHT);
        Axis y = Axis.covering(0, Arrays.stream(counts).max().orElse(1), 5, true, HEIGHT - Axis.BOTTOM, TOP);
        StringBuilder s = new StringBuilder(2048);
        s.append("<svg class=\"plot hist\" width=\"").append(WIDTH).append("\" height=\"").append(HEIGHT)
                .append("\" viewBox=\"0 0 ").append(WIDTH).append(' ').append(HEIGHT).append("\"><path class=\"grid\" d=\"");
        for (double tick : y.ticks()) {
            s.append('M').append(Axis.LEFT).append(' ').append(Svg.num(y.px(tick))).append('H').append(WIDTH - RIGHT);
        }
        s.append("\"/><path class=\"bar\" d=\"");
        for (int i = 0; i < bins; i++) {
            if (counts[i] > 0) {
                double x0 = x.px(from + i * width);
                double top = y.px(counts[i]);
                s.append('M').append(Svg.num(x0)).append(' ').append(Svg.num(y.px(0))).append('V').append(Svg.num(top))
                        .append('H').append(Svg.num(x.px(from + (i + 1) * width))).append('V')
                        .append(Svg.num(y.px(0))).append('Z');
            }
        }
        s.append("\"/>");
        Axis.frame(s, x, y, "lead (" + clock.unit() + ")", "runs");
        return s.append("</svg>").toString();
    }

    /** The smallest of 1, 2, 5, 10, 20, ... (or 0.5, 0.2, ...) that cuts {@code range} into at most MAX_BINS. */
    static double binWidth(double range) {
        return range > 0 ? Axis.roundStep(range / MAX_BINS) : 1;
    }
}
