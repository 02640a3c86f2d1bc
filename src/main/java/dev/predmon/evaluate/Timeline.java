package dev.predmon.evaluate;

import dev.predmon.abstraction.SafetyRule;
import dev.predmon.parse.LogReader;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The values a run's safety property watches (the battery level) over time, for plotting. Read with the same
 * parser and the same {@link SafetyRule#valueOf} as the built-in safety monitor, so the plotted violation is
 * the one the monitor reported.
 *
 * <p>Times are the log's own, and {@link #start} is the time of its first record, whatever it is: plots count
 * from there ({@link #sinceStart}), since a log with epoch times would otherwise put {@code 1,646,377,250} on
 * the axis. {@link #clock} says what a time unit is, so that a log whose clock is the tree's tick number is
 * labelled in ticks.
 *
 * @param start  time of the log's first record, in {@code clock} units
 * @param times  time stamps of the values, in {@code clock} units
 * @param values the watched values, same length
 * @param clock  what the times count
 */
public record Timeline(double start, double[] times, double[] values, Clock clock) {

    /** What a log's times count. */
    public enum Clock {
        /** Seconds, relative or since the epoch. */
        SECONDS("s", "s"),
        /** Ticks of the behaviour tree, for logs without time stamps. */
        TICKS("ticks", " ticks");

        private final String unit;
        private final String suffix;

        Clock(String unit, String suffix) {
            this.unit = unit;
            this.suffix = suffix;
        }

        /** The time axis's label: {@code time (s from start)}. */
        public String axisLabel() {
            return "time (" + unit + " from start)";
        }

        /** A duration in this clock, for text: {@code 3.9 s}, {@code 12 ticks}. */
        public String amount(double d) {
            return this == TICKS ? String.format(Locale.ROOT, "%.0f%s", d, suffix)
                    : String.format(Locale.ROOT, "%.1f %s", d, suffix);
        }
    }

    /** The timeline of {@code log} in seconds; see {@link #read(Path, SafetyRule, int, Clock)}. */
    public static Timeline read(Path log, SafetyRule rule, int maxPoints) throws IOException {
        return read(log, rule, maxPoints, Clock.SECONDS);
    }

    /** The timeline of {@code log}, thinned to at most {@code maxPoints} points (every n-th value kept). */
    public static Timeline read(Path log, SafetyRule rule, int maxPoints, Clock clock) throws IOException {
        List<double[]> points = new ArrayList<>();
        double[] first = {Double.NaN};
        LogReader.read(log, r -> {
            if (Double.isNaN(first[0])) {
                first[0] = r.time();
            }
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
        return new Timeline(Double.isNaN(first[0]) ? 0 : first[0], t, v, clock);
    }

    /** {@code time} (a log time, such as a warning's) counted from {@link #start}. */
    public double sinceStart(double time) {
        return time - start;
    }
}
