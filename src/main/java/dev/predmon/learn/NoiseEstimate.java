package dev.predmon.learn;

import dev.predmon.pipeline.LogTrace;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * How noisy a continuous sensor is, estimated from the training runs, and the hysteresis that absorbs it.
 *
 * <p>A real quantity drains or charges smoothly; a noisy sensor adds readings that zigzag: down, up, down again (or
 * up, down, up) within three changes. A trend that turns (a battery that starts charging) turns once and stays, so
 * it is no zigzag. The middle step of each zigzag measures the noise; the hysteresis is their upper quartile
 * (rounded up to a tenth), so that a reading that left a band by no more than the noise does not flip the band. A
 * sensor without zigzags in its training runs (a noise-free one) gets none: nothing changes for it.
 */
public final class NoiseEstimate {

    /** The quantile of zigzag steps that the hysteresis covers. */
    static final double QUANTILE = 0.75;

    private NoiseEstimate() {
    }

    /** The hysteresis per continuous rule input, from the readings of every run given; inputs without noise absent. */
    public static Map<String, Double> hysteresis(Collection<LogTrace.Run> runs) {
        Map<String, List<Double>> steps = new TreeMap<>();
        for (LogTrace.Run run : runs) {
            run.readings().forEach((input, values) -> steps.computeIfAbsent(input, k -> new ArrayList<>())
                    .addAll(zigzagSteps(values)));
        }
        Map<String, Double> h = new TreeMap<>();
        steps.forEach((input, list) -> {
            if (!list.isEmpty()) {
                h.put(input, Math.ceil(quantile(list, QUANTILE) * 10) / 10);
            }
        });
        return h;
    }

    /** The middle steps of the zigzags of one run's readings. */
    static List<Double> zigzagSteps(List<Double> values) {
        List<Double> changes = new ArrayList<>();
        for (int i = 1; i < values.size(); i++) {
            double d = values.get(i) - values.get(i - 1);
            if (d != 0) {
                changes.add(d); // repeated readings (a sensor read faster than it updates) are no change
            }
        }
        List<Double> steps = new ArrayList<>();
        for (int i = 1; i + 1 < changes.size(); i++) {
            double before = changes.get(i - 1);
            double middle = changes.get(i);
            double after = changes.get(i + 1);
            if (Math.signum(before) != Math.signum(middle) && Math.signum(middle) != Math.signum(after)) {
                steps.add(Math.abs(middle));
            }
        }
        return steps;
    }

    private static double quantile(List<Double> values, double q) {
        List<Double> sorted = values.stream().sorted().toList();
        int index = (int) Math.ceil(q * sorted.size()) - 1;
        return sorted.get(Math.max(0, Math.min(sorted.size() - 1, index)));
    }
}
