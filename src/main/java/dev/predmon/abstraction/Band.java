package dev.predmon.abstraction;

import java.util.Comparator;

/**
 * A numeric interval of reply values, each end open, closed or unbounded (an infinite bound is always open).
 * Bands of one rule must tile a contiguous stretch of the line: no value may fall in two bands, and no value
 * between the lowest and the highest band may fall in none. This is what makes a band table such as Section
 * 5.2's unambiguous at its boundaries.
 */
public record Band(double lower, boolean lowerClosed, double upper, boolean upperClosed) {

    /** Whether no value lies in this band. */
    public boolean isEmpty() {
        return lower > upper || (lower == upper && !(lowerClosed && upperClosed));
    }

    /** How far {@code v} lies outside this band; 0 inside. */
    double distance(double v) {
        if (contains(v)) {
            return 0;
        }
        return v <= lower ? lower - v : v - upper;
    }

    boolean contains(double v) {
        return (lowerClosed ? v >= lower : v > lower) && (upperClosed ? v <= upper : v < upper);
    }

    /** Interval notation, e.g. {@code (45, 50]}, {@code (-inf, 0]}. */
    @Override
    public String toString() {
        return (lowerClosed ? "[" : "(") + num(lower) + ", " + num(upper) + (upperClosed ? "]" : ")");
    }

    private static String num(double d) {
        if (Double.isInfinite(d)) {
            return d > 0 ? "+inf" : "-inf";
        }
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? Long.toString((long) d) : Double.toString(d);
    }

    /** Orders by lower end, a closed lower end first (it starts earlier). */
    public static final Comparator<Band> BY_LOWER = Comparator.comparingDouble(Band::lower)
            .thenComparing(b -> !b.lowerClosed());

    /** Whether this band and {@code next}, which starts no earlier, share a value. */
    public boolean overlaps(Band next) {
        return upper > next.lower || (upper == next.lower && upperClosed && next.lowerClosed);
    }

    /** Whether some value lies between this band and {@code next}, which starts no earlier. */
    public boolean leavesGapBefore(Band next) {
        return upper < next.lower || (upper == next.lower && !upperClosed && !next.lowerClosed);
    }

    /**
     * As a record's own: each component equal, the doubles as by {@link Double#compare}. Written out because the
     * record's is bootstrapped through {@code java.lang.runtime.ObjectMethods} on its first call, which spins
     * method handles for some 25 ms; validation, at every start, keys a map by bands.
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof Band b && Double.compare(lower, b.lower) == 0 && lowerClosed == b.lowerClosed
                && Double.compare(upper, b.upper) == 0 && upperClosed == b.upperClosed;
    }

    @Override
    public int hashCode() {
        int h = Double.hashCode(lower);
        h = 31 * h + Boolean.hashCode(lowerClosed);
        h = 31 * h + Double.hashCode(upper);
        return 31 * h + Boolean.hashCode(upperClosed);
    }
}
