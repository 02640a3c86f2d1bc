package dev.predmon.report;

import dev.predmon.evaluate.ForecastScore;

import java.util.List;
import java.util.Locale;

/**
 * The threshold sweep as a small SVG chart: as the probability threshold moves from low to high, the share of
 * violating runs warned (recall) and the share of safe runs warned (false alarms), each a line through its points,
 * and the threshold the models chose marked (one line, or a band where the folds chose differently). A good forecast
 * shows a wide range of thresholds where the first line is high and the second low.
 */
final class SweepChart {

    static final int WIDTH = 560;
    static final int HEIGHT = 280;
    private static final int RIGHT = 16;
    private static final int TOP = 46;
    private static final double ROW = 13;

    private SweepChart() {
    }

    /**
     * The chart of {@code sweep}; {@code low} and {@code high} are the lowest and highest threshold the judging
     * models chose (equal with one set of models, NaN when unknown).
     */
    static String svg(List<ForecastScore.Point> sweep, double low, double high) {
        Axis x = Axis.covering(0, 1, 10, false, Axis.LEFT, WIDTH - RIGHT);
        Axis y = Axis.covering(0, 100, 5, true, HEIGHT - Axis.BOTTOM, TOP);
        StringBuilder s = new StringBuilder(2048);
        s.append("<svg class=\"plot sweep\" width=\"").append(WIDTH).append("\" height=\"").append(HEIGHT)
                .append("\" viewBox=\"0 0 ").append(WIDTH).append(' ').append(HEIGHT).append("\"><path class=\"grid\" d=\"");
        for (double tick : x.ticks()) {
            s.append('M').append(Svg.num(x.px(tick))).append(' ').append(TOP).append('V').append(HEIGHT - Axis.BOTTOM);
        }
        for (double tick : y.ticks()) {
            s.append('M').append(Axis.LEFT).append(' ').append(Svg.num(y.px(tick))).append('H').append(WIDTH - RIGHT);
        }
        s.append("\"/>");
        String chosen = null;
        if (!Double.isNaN(low) && !Double.isNaN(high)) {
            if (high - low > 1e-9) {
                s.append("<rect class=\"chosen\" x=\"").append(Svg.num(x.px(low))).append("\" y=\"").append(TOP)
                        .append("\" width=\"").append(Svg.num(x.px(high) - x.px(low))).append("\" height=\"")
                        .append(HEIGHT - TOP - Axis.BOTTOM).append("\"/>");
                chosen = String.format(Locale.ROOT, "thresholds chosen %.2f-%.2f", low, high);
            } else {
                chosen = String.format(Locale.ROOT, "threshold chosen %.2f", low);
            }
            double mid = x.px((low + high) / 2);
            s.append("<path class=\"chosenline\" d=\"M").append(Svg.num(mid)).append(' ').append(TOP - 4).append('V')
                    .append(HEIGHT - Axis.BOTTOM).append("\"/>");
            double w = Svg.width(chosen, true);
            boolean onRight = mid + 4 + w <= WIDTH - 2;
            s.append(Svg.text("mchosen" + (onRight ? "" : " end"), onRight ? mid + 4 : mid - 4, 11 + ROW * 2, chosen));
        }
        line(s, sweep, x, y, "recall", true);
        line(s, sweep, x, y, "alarms", false);
        // the legend, each entry a row of its own above the plot
        legend(s, 0, "recall", "violating runs warned");
        legend(s, 1, "alarms", "safe runs warned (false alarms)");
        Axis.frame(s, x, y, "probability threshold", "% of runs");
        return s.append("</svg>").toString();
    }

    private static void line(StringBuilder s, List<ForecastScore.Point> sweep, Axis x, Axis y, String cls,
                             boolean recall) {
        StringBuilder d = new StringBuilder();
        StringBuilder dots = new StringBuilder();
        for (ForecastScore.Point p : sweep) {
            double share = recall ? share(p.warned(), p.violating()) : share(p.falseAlarms(), p.held());
            if (Double.isNaN(share)) {
                continue;
            }
            double px = x.px(p.threshold());
            double py = y.px(share * 100);
            d.append(d.isEmpty() ? 'M' : 'L').append(Svg.num(px)).append(' ').append(Svg.num(py));
            dots.append('M').append(Svg.num(px - 2.5)).append(' ').append(Svg.num(py)).append("a2.5 2.5 0 1 0 5 0a2.5 2.5 0 1 0 -5 0");
        }
        if (!d.isEmpty()) {
            s.append("<path class=\"").append(cls).append("\" d=\"").append(d).append("\"/>");
            s.append("<path class=\"").append(cls).append(" dot\" d=\"").append(dots).append("\"/>");
        }
    }

    private static void legend(StringBuilder s, int row, String cls, String words) {
        double baseline = 11 + ROW * row;
        double x0 = WIDTH - RIGHT - Svg.width(words, false) - 26;
        s.append("<path class=\"").append(cls).append("\" d=\"M").append(Svg.num(x0)).append(' ')
                .append(Svg.num(baseline - 4)).append("h18\"/>");
        s.append(Svg.text("legend", x0 + 22, baseline, words));
    }

    private static double share(int of, int all) {
        return all == 0 ? Double.NaN : of / (double) all;
    }
}
