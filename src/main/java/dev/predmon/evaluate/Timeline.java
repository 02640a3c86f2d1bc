package dev.predmon.evaluate;

import dev.predmon.abstraction.SafetyRule;
import dev.predmon.parse.LogReader;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The values a run's safety property watches (the battery level) over time, for plotting. Read with the same
 * parser and the same {@link SafetyRule#valueOf} as the built-in safety monitor, so the plotted violation is
 * the one the monitor reported.
 *
 * @param times  time stamps
 * @param values the watched values, same length
 */
public record Timeline(double[] times, double[] values) {

    /** The timeline of {@code log}, thinned to at most {@code maxPoints} points (every n-th value kept). */
    public static Timeline read(Path log, SafetyRule rule, int maxPoints) throws IOException {
        List<double[]> points = new ArrayList<>();
        LogReader.read(log, r -> {
            double v = rule.valueOf(r);
            if (!Double.isNaN(v)) {
                points.add(new double[] {r.time(), v});
            }
        }, p -> {
        });
        int step = Math.max(1, (points.size() + maxPoints - 1) / maxPoints);
        int n = (points.size() + step - 1) / step;
        double[] t = new double[n];
        double[] v = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = points.get(i * step)[0];
            v[i] = points.get(i * step)[1];
        }
        return new Timeline(t, v);
    }
}
