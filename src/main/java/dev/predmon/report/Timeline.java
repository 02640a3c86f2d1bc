package dev.predmon.report;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.compact.IoPair;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;
import dev.predmon.pipeline.PipelineListener;
import dev.predmon.pipeline.RunId;
import dev.predmon.pipeline.TracePipeline;
import dev.predmon.property.Bound;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The values a run's safety property watches (the battery level) over time, for plotting. Read with the same
 * parser and the same {@link Bound#valueOf} as the built-in safety monitor, so the plotted violation is
 * the one the monitor reported.
 *
 * <p>Times are the log's own, and {@link #start} is the time of the run's first record, whatever it is: plots
 * count from there ({@link #sinceStart}), since a log with epoch times would otherwise put {@code 1,646,377,250}
 * on the axis. {@link #clock} says what a time unit is, so that a log whose clock is the tree's tick number is
 * labelled in ticks.
 *
 * @param start  time of the log's first record, in {@code clock} units
 * @param times  time stamps of the values, in {@code clock} units
 * @param values the watched values, same length
 * @param clock  what the times count
 */
// Arrays: one number per point, read by index; a timeline is drawn, never compared or hashed.
@SuppressWarnings("ArrayRecordComponent")
public record Timeline(double start, double[] times, double[] values, Clock clock) {

    /**
     * The timeline of run {@code id}, cut into runs by the abstraction's rule as the monitor cuts it; the clock is the
     * log's own.
     */
    public static Timeline ofRun(RunId id, Abstraction abstraction, Bound rule, int maxPoints) throws IOException {
        int run = id.run();
        Path log = id.log();
        List<double[]> points = new ArrayList<>();
        double[] first = {Double.NaN};
        Clock[] clock = {Clock.SECONDS};
        int wanted = run;
        TracePipeline[] pipeline = new TracePipeline[1];
        pipeline[0] = new TracePipeline(abstraction, new PipelineListener() {
            @Override
            public void record(LogRecord r) {
                if (pipeline[0].run() != wanted) {
                    return;
                }
                clock[0] = r.clock();
                if (Double.isNaN(first[0])) {
                    first[0] = r.time();
                }
                double v = rule.valueOf(r);
                if (!Double.isNaN(v)) {
                    points.add(new double[] {r.time(), v});
                }
            }

            @Override
            public void pair(IoPair pair, LogRecord trigger) {
            }
        });
        try (RecordSource source = abstraction.format().read(log, RecordSink.of(pipeline[0]::accept, p -> { }))) {
            source.drain();
        }
        return thinned(points, first[0], maxPoints, clock[0]);
    }

    /** The points thinned to at most {@code maxPoints} (every n-th kept). */
    private static Timeline thinned(List<double[]> points, double first, int maxPoints, Clock clock) {
        int step = Math.max(1, (points.size() + maxPoints - 1) / maxPoints);
        int n = (points.size() + step - 1) / step;
        double[] t = new double[n];
        double[] v = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = points.get(i * step)[0];
            v[i] = points.get(i * step)[1];
        }
        return new Timeline(Double.isNaN(first) ? 0 : first, t, v, clock);
    }

    /** {@code time} (a log time, such as a warning's) counted from {@link #start}. */
    public double sinceStart(double time) {
        return time - start;
    }
}
