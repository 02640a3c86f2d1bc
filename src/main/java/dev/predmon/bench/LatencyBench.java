package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.LogWatcher;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.simulate.Scenario;

import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * Append-to-warning latency of {@code watch}: a writer thread appends a depleted run to a file; the main thread
 * runs {@code watch}'s {@link LogWatcher} loop on it, polling every {@code pollMicros} (watch's {@code --poll-ms}).
 * Everything before the record that triggers the warning is appended first and let through; then that record
 * is appended, and the time from the end of its write to the warning event is one sample. The time the poll that
 * read the record took (reading, parsing, matching, forecasting, the event) is kept beside it: the rest of the
 * latency is the poll pause and the operating system's scheduling. Rounds of warm-up, not measured, come first.
 *
 * <p>{@link #compare} measures two model sets in alternation (the models with their forecast, and the same machines
 * without), so that both see the same load: on a shared machine the tail of a latency moves with the load more than
 * with anything the monitor does.
 */
final class LatencyBench {

    /**
     * @param millis     one latency per run, sorted
     * @param processing per run, the time of the poll that read the warning's record, sorted
     */
    // Arrays: sorted samples for percentiles; a result is printed, never compared or hashed.
    @SuppressWarnings("ArrayRecordComponent")
    record Result(double[] millis, double[] processing, long pollMicros) {
        double median() {
            return percentile(millis, 0.5);
        }

        double p99() {
            return percentile(millis, 0.99);
        }

        double max() {
            return millis[millis.length - 1];
        }

        static double percentile(double[] sorted, double q) {
            return sorted[Math.min(sorted.length - 1, (int) Math.ceil(q * sorted.length) - 1)];
        }
    }

    /**
     * One unmeasured round per this many measured ones comes first, so that the tail measures the monitor, not the
     * compiler still at work on the warning's code.
     */
    static final int WARM_UP_SHARE = 5;

    private LatencyBench() {
    }

    /** One result per model set, their samples taken in alternation. */
    static List<Result> compare(Abstraction abstraction, List<ModelSet> sets, int runs, long pollMicros, Path dir)
            throws Exception {
        List<byte[][]> parts = new ArrayList<>(); // per set: the text before the warning's record, and the record
        for (ModelSet m : sets) {
            String[] run = warningRun(abstraction, m, dir);
            parts.add(new byte[][] {run[0].getBytes(StandardCharsets.UTF_8), run[1].getBytes(StandardCharsets.UTF_8)});
        }
        double[][] millis = new double[sets.size()][runs];
        double[][] processing = new double[sets.size()][runs];
        int warmUp = runs / WARM_UP_SHARE;
        for (int i = -warmUp; i < runs; i++) {
            for (int k = 0; k < sets.size(); k++) {
                double[] sample = once(parts.get(k)[0], parts.get(k)[1], abstraction, sets.get(k), pollMicros, dir);
                if (i >= 0) {
                    millis[k][i] = sample[0];
                    processing[k][i] = sample[1];
                }
            }
        }
        List<Result> results = new ArrayList<>();
        for (int k = 0; k < sets.size(); k++) {
            Arrays.sort(millis[k]);
            Arrays.sort(processing[k]);
            results.add(new Result(millis[k], processing[k], pollMicros));
        }
        return results;
    }

    /** One sample: {latency, time of the poll that read the trigger}, in ms. */
    private static double[] once(byte[] before, byte[] trigger, Abstraction abstraction, ModelSet models,
                               long pollMicros, Path dir) throws Exception {
        Path file = Files.createTempFile(dir, "predmon-latency", ".log");
        AtomicLong warnedAt = new AtomicLong();
        AtomicLong written = new AtomicLong();
        AtomicBoolean caughtUp = new AtomicBoolean();
        long polled = 0;
        PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, 0, e -> {
            if (e instanceof MonitorEvent.Warning) {
                warnedAt.set(System.nanoTime());
            }
        });
        try (OutputStream out = Files.newOutputStream(file);
             LogWatcher watcher = new LogWatcher(file, monitor, p -> {
             })) {
            out.write(before);
            out.flush();
            long records = before.length == 0 ? 0 : countRecords(before);
            Thread writer = new Thread(() -> {
                try {
                    while (!caughtUp.get()) {
                        LockSupport.parkNanos(100_000);
                    }
                    out.write(trigger);
                    out.flush();
                    written.set(System.nanoTime());
                } catch (Exception ex) {
                    throw new IllegalStateException(ex);
                }
            }, "predmon-bench-writer");
            writer.start();
            long deadline = System.nanoTime() + 10_000_000_000L;
            while (warnedAt.get() == 0 && System.nanoTime() < deadline) {
                long start = System.nanoTime();
                boolean read = watcher.poll();
                polled = System.nanoTime() - start;
                if (!caughtUp.get() && monitor.pipeline().records() >= records) {
                    caughtUp.set(true);
                }
                if (!read) {
                    LockSupport.parkNanos(pollMicros * 1000);
                }
            }
            writer.join();
            if (warnedAt.get() == 0) {
                throw new IllegalStateException("no warning within 10 s");
            }
        } finally {
            Files.deleteIfExists(file);
        }
        // The warning can be seen before the writer stores its clock; such a sample is ~0.
        return new double[] {Math.max(0, warnedAt.get() - written.get()) / 1e6, polled / 1e6};
    }

    /** A depleted run the models warn on, split at its first warning's record: the text before it and its seven lines. */
    static String[] warningRun(Abstraction abstraction, ModelSet models, Path dir) throws Exception {
        String[] parts = null;
        for (long seed = 20_000; parts == null && seed < 20_100; seed++) {
            parts = split(BenchData.text(Scenario.DEPLETED, seed), abstraction, models, dir);
        }
        if (parts == null) {
            throw new IllegalStateException("no simulated depleted run raised a warning with these models");
        }
        return parts;
    }

    static long countRecords(byte[] text) {
        String s = new String(text, StandardCharsets.UTF_8);
        return s.lines().filter(l -> l.contains(" intercepted:") || l.contains("\tintercepted:")
                || l.endsWith("intercepted:")).count();
    }

    /** The text before the warning's record and that record's seven lines, or null when no warning. */
    private static String[] split(String text, Abstraction abstraction, ModelSet models, Path dir) throws Exception {
        Path file = Files.createTempFile(dir, "predmon-latency", ".log");
        try {
            Files.writeString(file, text);
            long[] line = {-1};
            PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, 0, e -> {
                if (e instanceof MonitorEvent.Warning w && line[0] < 0) {
                    line[0] = w.line(); // the first: the text before it must raise none
                }
            });
            try (LogWatcher w = new LogWatcher(file, monitor, p -> {
            })) {
                w.drain();
            }
            if (line[0] < 0) {
                return null;
            }
            String[] lines = text.split("\n", -1);
            int start = (int) line[0] - 1; // the record's header line, 1-based
            StringBuilder before = new StringBuilder();
            for (int i = 0; i < start; i++) {
                before.append(lines[i]).append('\n');
            }
            StringBuilder trigger = new StringBuilder();
            for (int i = start; i < start + 7; i++) {
                trigger.append(lines[i]).append('\n');
            }
            return new String[] {before.toString(), trigger.toString()};
        } finally {
            Files.deleteIfExists(file);
        }
    }
}
