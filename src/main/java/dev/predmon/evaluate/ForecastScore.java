package dev.predmon.evaluate;

import java.util.ArrayList;
import java.util.List;

/**
 * How good the forecast was on the judged runs, which none of the models saw in training.
 *
 * <p>Every run weighs the same: a run's forecasts (one per pair before its violation or end) share one unit of
 * weight, so a long run does not outvote a short one. The outcome of every forecast of a run is whether that run
 * violated the property.
 *
 * @param runs        runs with at least one forecast
 * @param brier       the mean squared distance between probability and outcome (0 is perfect)
 * @param baseBrier   the same for a forecaster that always says the training runs' share of violations
 * @param ece         expected calibration error: the weighted mean gap between predicted and observed in the bins
 * @param reliability predicted probability against observed frequency, in ten bins of the probability
 * @param sweep       recall and false alarms as the threshold moves (a run is warned when its highest forecast
 *                    before the violation reaches the threshold)
 * @param judged      the warning rule the runs were judged by, scored on the runs with a forecast
 * @param rawValue    the raw-value baseline on the same runs ({@link ValueRule#rawValue})
 * @param chance      how far a calibrated forecast would stray on the same runs by chance alone: the yardstick of
 *                    {@code ece} and of each bin's observed frequency
 */
public record ForecastScore(int runs, double brier, double baseBrier, double ece, List<Bin> reliability,
                            List<Point> sweep, ValueRule judged, ValueRule rawValue, ChanceSpread chance) {

    /** Bins of the reliability table. */
    static final int BINS = 10;

    /**
     * One bin of the reliability table.
     *
     * @param from      lower edge of the probability
     * @param to        upper edge
     * @param weight    runs' worth of forecasts in the bin
     * @param forecasts forecasts in the bin
     * @param predicted their weighted mean probability
     * @param observed  the weighted share of them whose run violated
     * @param chanceLow  the observed share a calibrated forecast stays above in 19 draws of 20 on the same runs
     * @param chanceHigh the share it stays under in 19 draws of 20: an observed share outside is more than chance
     */
    public record Bin(double from, double to, double weight, int forecasts, double predicted, double observed,
                      double chanceLow, double chanceHigh) {

        /** Whether the observed share is within what chance gives a calibrated forecast on these runs. */
        public boolean withinChance() {
            return observed >= chanceLow - 1e-9 && observed <= chanceHigh + 1e-9;
        }
    }

    /**
     * The forecast rule at one threshold.
     *
     * @param threshold   the probability at which it warns
     * @param warned      violating runs warned before their violation
     * @param violating   violating runs
     * @param falseAlarms runs that held but were warned
     * @param held        runs that held
     */
    public record Point(double threshold, int warned, int violating, int falseAlarms, int held) {
    }

    /** The score of {@code runs} (runs without forecasts are left out); null when none has one. */
    public static ForecastScore of(List<RunResult> runs) {
        List<RunResult> scored = runs.stream().filter(r -> r.forecast() != null
                && !r.forecast().probabilities().isEmpty()).toList();
        if (scored.isEmpty()) {
            return null;
        }
        double brier = 0;
        double base = 0;
        double[] w = new double[BINS];
        double[] p = new double[BINS];
        double[] o = new double[BINS];
        int[] n = new int[BINS];
        for (RunResult r : scored) {
            double y = r.violationTime() != null ? 1 : 0;
            List<Double> ps = r.forecast().probabilities();
            double each = 1.0 / ps.size();
            for (double x : ps) {
                brier += each * (x - y) * (x - y);
                int b = ChanceSpread.bin(x, BINS);
                w[b] += each;
                p[b] += each * x;
                o[b] += each * y;
                n[b]++;
            }
            double br = r.forecast().baseRate();
            base += (br - y) * (br - y);
        }
        ChanceSpread chance = ChanceSpread.of(scored.stream().map(r -> r.forecast().probabilities()).toList(), BINS);
        List<Bin> bins = new ArrayList<>();
        double ece = 0;
        for (int b = 0; b < BINS; b++) {
            if (n[b] > 0) {
                bins.add(new Bin(b / (double) BINS, (b + 1) / (double) BINS, w[b], n[b], p[b] / w[b], o[b] / w[b],
                        chance.observedLow().get(b), chance.observedHigh().get(b)));
                ece += Math.abs(p[b] - o[b]);
            }
        }
        List<Point> sweep = new ArrayList<>();
        for (int i = 1; i <= 9; i++) {
            sweep.add(point(scored, i / 10.0));
        }
        return new ForecastScore(scored.size(), brier / scored.size(), base / scored.size(), ece / scored.size(),
                List.copyOf(bins), List.copyOf(sweep), ValueRule.judged(runs), ValueRule.rawValue(runs), chance);
    }

    /** The forecast rule at threshold {@code t} over {@code runs}. */
    static Point point(List<RunResult> runs, double t) {
        int warned = 0;
        int violating = 0;
        int alarms = 0;
        int held = 0;
        for (RunResult r : runs) {
            boolean reached = r.forecast().peak() >= t;
            if (r.violationTime() != null) {
                violating++;
                warned += reached ? 1 : 0;
            } else {
                held++;
                alarms += reached ? 1 : 0;
            }
        }
        return new Point(t, warned, violating, alarms, held);
    }
}
