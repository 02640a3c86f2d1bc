package dev.predmon.evaluate;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

/**
 * Median, minimum and maximum of a sample; all null for an empty one.
 *
 * @param n      sample size
 * @param median the median (mean of the two middle values for an even size)
 * @param min    the least value
 * @param max    the greatest value
 */
public record Stats(int n, Double median, Double min, Double max) {

    /** Statistics of {@code values}. */
    public static Stats of(Collection<Double> values) {
        if (values.isEmpty()) {
            return new Stats(0, null, null, null);
        }
        List<Double> v = new ArrayList<>(values);
        v.sort(null);
        int n = v.size();
        double median = n % 2 == 1 ? v.get(n / 2) : (v.get(n / 2 - 1) + v.get(n / 2)) / 2;
        return new Stats(n, median, v.get(0), v.get(n - 1));
    }
}
