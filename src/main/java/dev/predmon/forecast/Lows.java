package dev.predmon.forecast;

import java.util.Arrays;

/**
 * How low training runs went while safe, split by outcome: the violating runs' and the safe runs' lowest values of
 * the property (sorted). Of the runs that went as low as a value {@code v}, it counts how many violated, which is
 * P(violation | the property reads v) without a machine, and, kept per state, P(violation | this state, v).
 */
public final class Lows {

    private final double[] safe;
    private final double[] violating;
    /** For each violating low, the highest smoothed rate at it or above: computed on first use, for one prior. */
    private double[] envelope;
    private double envelopePrior = Double.NaN;
    private double envelopeBase = Double.NaN;

    /** @param safe the lowest values of the runs that held; {@code violating}, of the runs that violated */
    public Lows(double[] safe, double[] violating) {
        this.safe = safe.clone();
        this.violating = violating.clone();
        Arrays.sort(this.safe);
        Arrays.sort(this.violating);
    }

    /** The safe runs' lowest values, sorted. */
    public double[] safe() {
        return safe.clone();
    }

    /** How many runs held (with a reading). */
    public int safeCount() {
        return safe.length;
    }

    /** The violating runs' lowest values before their violation, sorted. */
    public double[] violating() {
        return violating.clone();
    }

    /** Runs that went as low as {@code value} while safe; every run when the value is unknown (NaN). */
    public int runs(double value) {
        return violating(value) + atMost(safe, value);
    }

    /** Violating runs that went as low as {@code value} while safe; all of them when the value is unknown (NaN). */
    public int violating(double value) {
        return atMost(violating, value);
    }

    /**
     * The violation rate at {@code value}, {@code (k + prior * base) / (n + prior)} over the runs that went as low, made
     * non-increasing in the value: the rate at a violating run's low above {@code value} counts too, since that run
     * went below its last safe reading on its way to the violation.
     */
    public synchronized double monotoneRate(double value, double prior, double base) {
        if (envelope == null || prior != envelopePrior || base != envelopeBase) {
            envelope = new double[violating.length + 1];
            for (int i = violating.length - 1; i >= 0; i--) {
                envelope[i] = Math.max(envelope[i + 1], rate(violating[i], prior, base));
            }
            envelopePrior = prior;
            envelopeBase = base;
        }
        int above = atMost(violating, value); // the first violating low above value
        return Math.max(rate(value, prior, base), envelope[above]);
    }

    private double rate(double value, double prior, double base) {
        return (violating(value) + prior * base) / (runs(value) + prior);
    }

    private static int atMost(double[] sorted, double value) {
        if (Double.isNaN(value)) {
            return sorted.length;
        }
        int lo = 0;
        int hi = sorted.length;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (sorted[mid] <= value) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Lows l && Arrays.equals(safe, l.safe) && Arrays.equals(violating, l.violating);
    }

    @Override
    public int hashCode() {
        return 31 * Arrays.hashCode(safe) + Arrays.hashCode(violating);
    }

    @Override
    public String toString() {
        return "Lows[" + violating.length + " violating, " + safe.length + " safe]";
    }
}
