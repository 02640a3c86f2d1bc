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
