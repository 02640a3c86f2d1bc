package dev.predmon.evaluate;

import java.util.ArrayList;
import java.util.List;

/**
 * How good a probability forecast was on judged runs, whatever property it forecasts: the Brier score against a
 * forecaster that always says the base rate, the expected calibration error and the reliability table.
 *
 * <p>Every run weighs the same: a run's forecasts share one unit of weight, so a long run does not outvote a short
 * one. Each forecast carries its own outcome (1 when what it forecast happened): for a forecast of the run's
 * violation, whether the run violated the property; for a deadline forecast, whether the obligation it was about
 * missed its deadline.
 *
 * @param runs        runs with at least one forecast
 * @param forecasts   forecasts scored
 * @param violating   of the runs, those with an outcome of 1 (the run violated the property)
 * @param brier       the weighted mean squared distance between probability and outcome (0 is perfect)
 * @param baseBrier   the same for a forecaster that always says each run's base rate; null when a run has none
 * @param ece         expected calibration error: the weighted mean gap between predicted and observed in the bins
 * @param bins        predicted probability against observed frequency, in ten bins of the probability (the bins
 *                    with a forecast)
 * @param eceChance   the calibration error a calibrated forecast stays under on the same runs by chance alone, 9
 *                    times in 10 ({@link ChanceSpread}): an {@code ece} below it is no evidence of miscalibration
 */
public record Reliability(int runs, int forecasts, int violating, double brier, Double baseBrier, double ece,
                          List<Bin> bins, double eceChance) {

    /** Bins of the reliability table. */
    static final int BINS = 10;

    public Reliability {
        bins = List.copyOf(bins);
    }

    /**
     * One bin of the reliability table.
     *
     * @param from      lower edge of the probability
     * @param to        upper edge
     * @param weight    runs' worth of forecasts in the bin
     * @param forecasts forecasts in the bin
     * @param predicted their weighted mean probability
     * @param observed  the weighted share of them whose outcome was 1
     * @param chanceLow  the observed share a calibrated forecast stays above on the same runs, 19 times in 20
     * @param chanceHigh the share it stays under, 19 times in 20: an observed share outside the two is more than chance
     */
    public record Bin(double from, double to, double weight, int forecasts, double predicted, double observed,
                      double chanceLow, double chanceHigh) {

        /** Whether the observed share is within what chance gives a calibrated forecast on these runs. */
        public boolean withinChance() {
            return observed >= chanceLow - 1e-9 && observed <= chanceHigh + 1e-9;
        }
    }

    /**
     * The forecasts of one run.
     *
     * @param probabilities each forecast's probability, in order
     * @param outcomes      each forecast's outcome, 0 or 1, same length
     * @param baseRate      what the base-rate forecaster says for this run, null when not known
     */
    public record Run(List<Double> probabilities, List<Integer> outcomes, Double baseRate) {

        public Run {
            probabilities = List.copyOf(probabilities);
            outcomes = List.copyOf(outcomes);
            if (probabilities.size() != outcomes.size()) {
                throw new IllegalArgumentException(outcomes.size() + " outcomes for " + probabilities.size()
                        + " probabilities");
            }
        }

        /** A run whose every forecast has the run's outcome. */
        public static Run of(List<Double> probabilities, boolean violated, Double baseRate) {
            return new Run(probabilities, probabilities.stream().map(p -> violated ? 1 : 0).toList(), baseRate);
        }
    }

    /** The score of {@code runs} (a run without a forecast is left out); null when none has one. */
    public static Reliability of(List<Run> runs) {
        List<Run> scored = runs.stream().filter(r -> !r.probabilities().isEmpty()).toList();
        if (scored.isEmpty()) {
            return null;
        }
        double brier = 0;
        double base = 0;
        double[] w = new double[BINS];
        double[] p = new double[BINS];
        double[] o = new double[BINS];
        int[] n = new int[BINS];
        int forecasts = 0;
        int violating = 0;
        for (Run r : scored) {
            List<Double> ps = r.probabilities();
            double each = 1.0 / ps.size();
            double br = r.baseRate() == null ? Double.NaN : r.baseRate();
            boolean violated = false;
            for (int i = 0; i < ps.size(); i++) {
                double x = ps.get(i);
                double y = r.outcomes().get(i);
                violated |= y > 0;
                brier += each * (x - y) * (x - y);
                int b = ChanceSpread.bin(x, BINS);
                w[b] += each;
                p[b] += each * x;
                o[b] += each * y;
                n[b]++;
            }
            if (r.outcomes().stream().allMatch(y -> y.equals(r.outcomes().get(0)))) {
                double y = r.outcomes().get(0);
                base += (br - y) * (br - y); // one outcome for the whole run: its squared distance, as it is
            } else {
                for (int y : r.outcomes()) {
                    base += each * (br - y) * (br - y);
                }
            }
            forecasts += ps.size();
            violating += violated ? 1 : 0;
        }
        ChanceSpread chance = ChanceSpread.of(scored.stream().map(Run::probabilities).toList(), BINS);
        List<Bin> bins = new ArrayList<>();
        double ece = 0;
        for (int b = 0; b < BINS; b++) {
            if (n[b] > 0) {
                bins.add(new Bin(b / (double) BINS, (b + 1) / (double) BINS, w[b], n[b], p[b] / w[b], o[b] / w[b],
                        chance.observedLow().get(b), chance.observedHigh().get(b)));
                ece += Math.abs(p[b] - o[b]);
            }
        }
        int k = scored.size();
        return new Reliability(k, forecasts, violating, brier / k, Double.isNaN(base) ? null : base / k, ece / k,
                bins, chance.eceBound());
    }
}
