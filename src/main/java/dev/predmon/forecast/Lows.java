package dev.predmon.forecast;

import java.util.Arrays;

/**
 * How low training runs went while safe, split by outcome: the violating runs' and the safe runs' lowest values of
 * the property (sorted). Of the runs that went as low as a value {@code v}, it counts how many violated, which is
 * P(violation | the property reads v) without a machine, and, kept per state, P(violation | this state, v).
 *
 * <p>Immutable. The model's own lows also carry the smoothing of its value rate ({@link #smoothed}), with the
 * monotone envelope of that rate computed once, when they are made.
 */
public final class Lows {

    private final double[] safe;
    private final double[] violating;
    /** The strength of the prior the rates are smoothed with, in runs; NaN for lows without a smoothing. */
    private final double prior;
    /** The rate the smoothing pulls towards; NaN for lows without a smoothing. */
    private final double base;
    /** For each violating low, the highest smoothed rate at it or above (one more, 0, past the last); null without. */
    private final double[] envelope;

    /** @param safe the lowest values of the runs that held; {@code violating}, of the runs that violated */
    public Lows(double[] safe, double[] violating) {
        this(sorted(safe), sorted(violating), Double.NaN, Double.NaN);
    }

    private Lows(double[] safe, double[] violating, double prior, double base) {
        this.safe = safe;
        this.violating = violating;
        this.prior = prior;
        this.base = base;
        if (Double.isNaN(prior)) {
            this.envelope = null;
        } else {
            this.envelope = new double[violating.length + 1];
            for (int i = violating.length - 1; i >= 0; i--) {
                envelope[i] = Math.max(envelope[i + 1], rate(violating[i]));
            }
        }
    }

    /**
     * These lows with their rates smoothed as {@code (k + prior * base) / (n + prior)} over the {@code n} runs that
     * went as low, {@code k} of them violating: what {@link #monotoneRate} answers with. The same lows (equal).
     */
    public Lows smoothed(double prior, double base) {
        return Double.compare(prior, this.prior) == 0 && Double.compare(base, this.base) == 0 ? this
                : new Lows(safe, violating, prior, base);
    }

    /** The safe runs' lowest values, sorted. */
    public double[] safe() {
        return safe.clone();
    }

    /** How many runs held (with a reading). */
    public int safeCount() {
        return safe.length;
    }

    /**
     * The lowest value a run that held went to (NaN without one). No margin is taken below it: a robot stuck on
     * its way to recover drains past it in seconds, and a margin of the lowest runs' spacing (four points on the
     * public recordings) left a warning one reading before the violation.
     */
    public double safeFloor() {
        return safe.length == 0 ? Double.NaN : safe[0];
    }

    /** The violating runs' lowest values before their violation, sorted. */
    public double[] violating() {
        return violating.clone();
    }

    /** Runs that went as low as {@code value} while safe; every run when the value is unknown (NaN). */
    public int runs(double value) {
        return violating(value) + atMost(safe, value);
    }

    /**
     * Runs that went as low as {@code value}, with the safe runs' edge: below the lowest value any safe run went to,
     * a new safe run still goes that low about once in {@code n + 1} (its low is as likely to be the lowest as any of
     * the {@code n} seen), so {@code n / (n + 1)} of a safe run is counted there instead of none. Without it, a value
     * just past the lowest of a few safe runs would read as certain violation.
     */
    public double weight(double value) {
        double edge = safe.length > 0 && value < safe[0] ? safe.length / (safe.length + 1.0) : 0.0;
        return runs(value) + edge;
    }

    /** Violating runs that went as low as {@code value} while safe; all of them when the value is unknown (NaN). */
    public int violating(double value) {
        return atMost(violating, value);
    }

    /**
     * The violation rate at {@code value}, smoothed ({@link #smoothed}) over the runs that went as low, made
     * non-increasing in the value: the rate at a violating run's low above {@code value} counts too, since that run
     * went below its last safe reading on its way to the violation.
     *
     * @throws IllegalStateException on lows without a smoothing
     */
    public double monotoneRate(double value) {
        if (envelope == null) {
            throw new IllegalStateException("lows without a smoothing have no rate: see smoothed()");
        }
        int above = atMost(violating, value); // the first violating low above value
        return Math.max(rate(value), envelope[above]);
    }

    private double rate(double value) {
        return (violating(value) + prior * base) / (weight(value) + prior);
    }

    private static double[] sorted(double[] values) {
        double[] copy = values.clone();
        Arrays.sort(copy);
        return copy;
    }

    /** How many of {@code sorted} are at most {@code value}; all of them when it is NaN. */
    static int atMost(double[] sorted, double value) {
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
