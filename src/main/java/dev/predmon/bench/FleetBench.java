package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.parse.LogRecord;
import dev.predmon.simulate.Scenario;

import java.io.IOException;
import java.io.OutputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;
import java.util.concurrent.locks.LockSupport;

/**
 * {@code watch} with many logs in one process, against one log: {@link Fleet#poll()} in the loop {@code watch} runs
 * (a pass over every log, then the pause), on the polling thread, whose CPU time is what is counted. Per fleet size:
 * <ul>
 *   <li><b>catch-up</b>: CPU per record while the loop reads logs written before it started (parse, abstract,
 *       compact, match, and the polling);</li>
 *   <li><b>idle</b>: the share of a core spent polling logs nothing is appended to;</li>
 *   <li><b>robot pace</b>: a writer thread appends to every log at the simulated robot's own pace (records per second
 *       of its log's clock); the loop's share of a core and its CPU per record;</li>
 *   <li><b>append to warning</b>: every log holds a depleted run up to the record that triggers the warning; the
 *       writer appends that record to the logs one by one, in random order, 1 to 3 ms apart, and each log's time
 *       from the end of the write to its warning event is one sample (as {@link LatencyBench} measures one log).</li>
 * </ul>
 */
final class FleetBench {

    /**
     * @param logs          logs watched at once
     * @param catchUpNanos  CPU ns per record reading logs written before
     * @param idleCore      share of one core (0..1) polling logs that do not grow
     * @param paceRate      records per second appended to each log at robot pace
     * @param paceCore      share of one core at robot pace
     * @param paceNanos     CPU ns per record at robot pace
     * @param millis        append-to-warning latencies, sorted
     * @param pollMicros    the pause after each pass
     */
    record Result(int logs, double catchUpNanos, double idleCore, double paceRate, double paceCore, double paceNanos,
                  double[] millis, long pollMicros) {
        double percentile(double q) {
            return millis[Math.min(millis.length - 1, (int) Math.ceil(q * millis.length) - 1)];
        }
    }

    private final Abstraction abstraction;
    private final ModelSet models;
    private final long pollMicros;
    private final Path dir;
    private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    private final byte[] before;
    private final byte[] trigger;
    private final long beforeRecords;
    private final List<byte[]> run;
    private final double robotRate;
    /** How long the robot-pace phase runs; the idle phase runs half as long. */
    private final long paceNanos;

    private FleetBench(Abstraction abstraction, ModelSet models, long pollMicros, double seconds, Path dir)
            throws Exception {
        this.paceNanos = (long) (seconds * 1e9);
        this.abstraction = abstraction;
        this.models = models;
        this.pollMicros = pollMicros;
        this.dir = dir;
        String[] parts = LatencyBench.warningRun(abstraction, models, dir);
        this.before = parts[0].getBytes(StandardCharsets.UTF_8);
        this.trigger = parts[1].getBytes(StandardCharsets.UTF_8);
        this.beforeRecords = LatencyBench.countRecords(before);
        String text = BenchData.text(Scenario.DEPLETED, 20_001);
        this.run = records(text);
        List<LogRecord> parsed = BenchData.records(text);
        this.robotRate = parsed.size() / (parsed.get(parsed.size() - 1).time() - parsed.get(0).time());
    }

    /**
     * Measures fleets of each size in {@code sizes}, about {@code samples} latencies each.
     *
     * @param seconds how long the loop runs at robot pace per size (and half that idle)
     */
    static List<Result> run(Abstraction abstraction, ModelSet models, List<Integer> sizes, int samples, long pollMicros,
                            double seconds, Path dir) throws Exception {
        FleetBench b = new FleetBench(abstraction, models, pollMicros, seconds, dir);
        b.measure(Math.min(10, sizes.get(sizes.size() - 1)), Math.min(20, samples)); // warm-up: JIT, page cache
        List<Result> out = new ArrayList<>();
        for (int n : sizes) {
            out.add(b.measure(n, samples));
        }
        return out;
    }

    private Result measure(int logs, int samples) throws Exception {
        int rounds = Math.max(1, (samples + logs - 1) / logs);
        double[] millis = new double[rounds * logs];
        long catchUpCpu = 0;
        long caughtUp = 0;
        double idle = 0;
        for (int r = 0; r < rounds; r++) {
            Path round = Files.createTempDirectory(dir, "predmon-fleet");
            try {
                List<Path> files = new ArrayList<>();
                for (int i = 0; i < logs; i++) {
                    files.add(Files.write(round.resolve("robot-" + i + ".log"), before));
                }
                long[] warnedAt = new long[logs];
                Map<WatchedLog, Integer> index = new HashMap<>();
                try (Fleet fleet = new Fleet(models, abstraction, 0, abstraction.confirm(), (log, e) -> {
                    if (e instanceof MonitorEvent.Warning) {
                        warnedAt[index.get(log)] = System.nanoTime();
                    }
                })) {
                    for (Path f : files) {
                        index.put(fleet.add(f), index.size());
                    }
                    long cpu = cpu();
                    while (fleet.logs().stream().anyMatch(l -> l.monitor().pipeline().records() < beforeRecords)) {
                        fleet.poll();
                    }
                    catchUpCpu += cpu() - cpu;
                    caughtUp += logs * beforeRecords;
                    if (r == 0) {
                        idle = idle(fleet);
                    }
                    latencies(fleet, files, warnedAt, new Random(r), millis, r * logs);
                }
            } finally {
                delete(round);
            }
        }
        Arrays.sort(millis);
        double[] pace = pace(logs);
        return new Result(logs, (double) catchUpCpu / caughtUp, idle, robotRate, pace[0], pace[1], millis, pollMicros);
    }

    /** The share of a core the loop spends on logs that do not grow. */
    private double idle(Fleet fleet) throws IOException {
        long cpu = cpu();
        long start = System.nanoTime();
        while (System.nanoTime() - start < paceNanos / 2) {
            pass(fleet);
        }
        return (double) (cpu() - cpu) / (System.nanoTime() - start);
    }

    private void latencies(Fleet fleet, List<Path> files, long[] warnedAt, Random random, double[] into, int at)
            throws Exception {
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < files.size(); i++) {
            order.add(i);
        }
        Collections.shuffle(order, random);
        long[] writtenAt = new long[files.size()];
        Thread writer = new Thread(() -> {
            for (int i : order) {
                try (OutputStream out = Files.newOutputStream(files.get(i), StandardOpenOption.APPEND)) {
                    out.write(trigger);
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
                writtenAt[i] = System.nanoTime(); // closed: the record is in the file
                LockSupport.parkNanos(1_000_000L + random.nextInt(2_000_000));
            }
        }, "predmon-bench-writer");
        writer.start();
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (Arrays.stream(warnedAt).anyMatch(t -> t == 0) && System.nanoTime() < deadline) {
            pass(fleet);
        }
        writer.join();
        for (int i = 0; i < files.size(); i++) {
            if (warnedAt[i] == 0) {
                throw new IllegalStateException("log " + i + " of " + files.size() + ": no warning within 60 s");
            }
            // The warning can be seen before the writer stores its clock; such a sample is ~0.
            into[at + i] = Math.max(0, warnedAt[i] - writtenAt[i]) / 1e6;
        }
    }

    /** {share of a core, CPU ns per record} with every log growing at the robot's pace. */
    private double[] pace(int logs) throws Exception {
        Path round = Files.createTempDirectory(dir, "predmon-fleet-pace");
        try (Fleet fleet = new Fleet(models, abstraction, 0, abstraction.confirm(), (log, e) -> { })) {
            List<OutputStream> outs = new ArrayList<>();
            for (int i = 0; i < logs; i++) {
                Path f = Files.createFile(round.resolve("robot-" + i + ".log"));
                outs.add(Files.newOutputStream(f, StandardOpenOption.APPEND));
                fleet.add(f);
            }
            long start = System.nanoTime();
            // Each log starts at its own point of the run, as robots do not start together.
            int[] cursor = new int[logs];
            for (int i = 0; i < logs; i++) {
                cursor[i] = (int) ((long) i * run.size() / Math.max(1, logs));
            }
            Thread writer = new Thread(() -> {
                long written = 0;
                while (System.nanoTime() - start < paceNanos) {
                    long due = (long) ((System.nanoTime() - start) / 1e9 * robotRate);
                    try {
                        for (; written < due; written++) {
                            for (int i = 0; i < logs; i++) {
                                outs.get(i).write(run.get(cursor[i]));
                                cursor[i] = (cursor[i] + 1) % run.size();
                            }
                        }
                        for (OutputStream o : outs) {
                            o.flush();
                        }
                    } catch (IOException e) {
                        throw new IllegalStateException(e);
                    }
                    LockSupport.parkNanos(5_000_000L);
                }
            }, "predmon-bench-pace");
            writer.start();
            long cpu = cpu();
            long t0 = System.nanoTime();
            while (writer.isAlive()) {
                pass(fleet);
            }
            pass(fleet);
            long used = cpu() - cpu;
            double wall = System.nanoTime() - t0;
            long records = fleet.logs().stream().mapToLong(l -> l.monitor().pipeline().records()).sum();
            for (OutputStream o : outs) {
                o.close();
            }
            return new double[] {used / wall, (double) used / Math.max(1, records)};
        } finally {
            delete(round);
        }
    }

    /** One pass of watch's loop: every log polled once, then the pause. */
    private void pass(Fleet fleet) throws IOException {
        fleet.poll();
        LockSupport.parkNanos(pollMicros * 1000);
    }

    private long cpu() {
        return threads.getCurrentThreadCpuTime();
    }

    /** A log text cut into its records, each with its lines. */
    private static List<byte[]> records(String text) {
        List<byte[]> out = new ArrayList<>();
        StringBuilder current = new StringBuilder();
        for (String line : text.split("\n", -1)) {
            if (line.endsWith("intercepted:") && current.length() > 0) {
                out.add(current.toString().getBytes(StandardCharsets.UTF_8));
                current.setLength(0);
            }
            if (!line.isEmpty()) {
                current.append(line).append('\n');
            }
        }
        if (current.length() > 0) {
            out.add(current.toString().getBytes(StandardCharsets.UTF_8));
        }
        return out;
    }

    private static void delete(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }
}
