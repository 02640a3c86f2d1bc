package dev.predmon.evaluate;

import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;

/**
 * How far a perfectly calibrated forecast would stray on the same runs by chance alone: the yardstick for a reliability
 * table and an expected calibration error computed on a few dozen runs, where one surprising run moves a bin by tens of
 * points.
 *
 * <p>It keeps every run's forecasts as they are and draws the outcomes as a calibrated forecast says they come out:
 * in each bin of the probability, a run's share of the bin (a run weighs one, shared by its forecasts, as in the
 * reliability table) comes true with the mean of its forecasts in that bin, so a run that said 0.05 early and 0.95 late
 * is judged in each bin by what it said there. Bins are drawn one from another independently, which makes the bound on
 * the error an approximation (a run's bins share one outcome) and each bin's range exact for a calibrated forecast. Over {@value #DRAWS} draws from a fixed seed (the same runs give the same figures), it keeps the
 * expected calibration error 9 draws in 10 stay under, and per bin the range 9 draws in 10 of the observed frequency
 * fall in. An observed frequency outside its bin's range, or an error above that bound, is more than chance.
 *
 * @param eceBound    the calibration error a calibrated forecast stays under in 9 draws of 10
 * @param observedLow by bin, the 5th percentile of the observed frequency a calibrated forecast shows (NaN for a bin
 *                    without forecasts)
 * @param observedHigh by bin, the 95th percentile
 */
public record ChanceSpread(double eceBound, List<Double> observedLow, List<Double> observedHigh) {

    /** Draws of the outcomes. */
    static final int DRAWS = 2000;
    /** The seed of the draws: the same runs always give the same spread. */
    private static final long SEED = 20_261_127L;

    public ChanceSpread {
        observedLow = List.copyOf(observedLow);
        observedHigh = List.copyOf(observedHigh);
    }

    /**
     * The spread of {@code runs} (each run's forecasts, none empty) in {@code bins} equal bins of the probability.
     */
    public static ChanceSpread of(List<List<Double>> runs, int bins) {
        int n = runs.size();
        // per run and bin: the run's weight in the bin and the mean of its forecasts there
        double[][] weight = new double[n][bins];
        double[][] chance = new double[n][bins];
        double[] w = new double[bins];
        double[] p = new double[bins];
        for (int r = 0; r < n; r++) {
            List<Double> ps = runs.get(r);
            double each = 1.0 / ps.size();
            for (double x : ps) {
                int b = bin(x, bins);
                weight[r][b] += each;
                chance[r][b] += each * x;
                w[b] += each;
                p[b] += each * x;
            }
            for (int b = 0; b < bins; b++) {
                chance[r][b] = weight[r][b] > 0 ? chance[r][b] / weight[r][b] : 0;
            }
        }
        SplittableRandom random = new SplittableRandom(SEED);
        double[] eces = new double[DRAWS];
        double[][] observed = new double[bins][DRAWS];
        for (int d = 0; d < DRAWS; d++) {
            double[] o = new double[bins];
            for (int r = 0; r < n; r++) {
                for (int b = 0; b < bins; b++) {
                    if (weight[r][b] > 0 && random.nextDouble() < chance[r][b]) {
                        o[b] += weight[r][b];
                    }
                }
            }
            double ece = 0;
            for (int b = 0; b < bins; b++) {
                if (w[b] > 0) {
                    ece += Math.abs(p[b] - o[b]);
                    observed[b][d] = o[b] / w[b];
                }
            }
            eces[d] = n == 0 ? 0 : ece / n;
        }
        Double[] low = new Double[bins];
        Double[] high = new Double[bins];
        for (int b = 0; b < bins; b++) {
            if (w[b] > 0) {
                Arrays.sort(observed[b]);
                low[b] = quantile(observed[b], 0.05);
                high[b] = quantile(observed[b], 0.95);
            } else {
                low[b] = Double.NaN;
                high[b] = Double.NaN;
            }
        }
        Arrays.sort(eces);
        return new ChanceSpread(quantile(eces, 0.9), Arrays.asList(low), Arrays.asList(high));
    }

    /** The bin of probability {@code x} among {@code bins} equal bins of [0, 1]. */
    static int bin(double x, int bins) {
        return Math.max(0, Math.min(bins - 1, (int) (x * bins)));
    }

    /** Whether the observed frequency {@code observed} of bin {@code b} is within what chance gives a calibrated forecast. */
    public boolean withinChance(int b, double observed) {
        double low = observedLow.get(b);
        double high = observedHigh.get(b);
        return !Double.isNaN(low) && observed >= low - 1e-9 && observed <= high + 1e-9;
    }

    private static double quantile(double[] sorted, double q) {
        if (sorted.length == 0) {
            return Double.NaN;
        }
        int i = (int) Math.ceil(q * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
    }
}
