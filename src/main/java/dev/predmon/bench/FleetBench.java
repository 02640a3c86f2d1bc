package dev.predmon.bench;

import com.sun.management.OperatingSystemMXBean;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WatchedLog;

import java.io.OutputStream;
import java.lang.management.CompilationMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.locks.LockSupport;
import java.util.stream.IntStream;

/**
 * {@code watch} with many logs in one process, against one log: {@link Fleet#follow} on a thread of its own, as
 * {@code watch} runs it (woken by the operating system's file-change notification, or polling every log with
 * {@code --polling}). CPU is the whole process's CPU time (the following thread, the JDK's notification thread, the
 * garbage collector and the compiler), less that of the bench's own appending thread; it is CPU time, not a share of a
 * busy machine's wall clock. Per fleet size:
 * <ul>
 *   <li><b>catch-up</b>: CPU per record while {@link Fleet#poll()} reads logs written before (parse, abstract,
 *       compact, match, and the polling);</li>
 *   <li><b>idle</b>: the share of a core spent following logs nothing is appended to (and, apart, the following
 *       thread's own share);</li>
 *   <li><b>robot pace</b>: another process appends to every log at the simulated robot's own pace (records per
 *       second of its log's clock); the share of a core, the CPU per record, and append-to-warning latencies of a
 *       tenth as many logs more meanwhile ({@link RobotPace});</li>
 *   <li><b>append to warning</b>: every log holds a depleted run up to the record that triggers the warning; the
 *       bench appends that record to the logs one by one, in random order, 1 to 3 ms apart, and each log's time
 *       from the start of the write to its warning event is one sample (as {@link LatencyBench} measures one log).</li>
 * </ul>
 */
final class FleetBench {

    /**
     * @param logs          logs watched at once
     * @param catchUpNanos  CPU ns per record reading logs written before
     * @param idleCore      share of one core (0..1) the process spends following logs that do not grow
     * @param idleLoopCore  the same, of the following thread alone
     * @param paceRate      records per second each log should grow by at robot pace
     * @param pace          the robot-pace phase: CPU, the rates written and read, latencies meanwhile
     * @param millis        append-to-warning latencies of a quiet fleet, sorted
     * @param early         logs of the quiet fleet that warned before the warning's record was written (no sample)
     */
    // Arrays: sorted samples for percentiles; a result is printed, never compared or hashed.
    @SuppressWarnings("ArrayRecordComponent")
    record Result(int logs, double catchUpNanos, double idleCore, double idleLoopCore, double paceRate,
                  RobotPace.Load pace, double[] millis, int early) {
        double percentile(double q) {
            return percentile(millis, q);
        }

        /** The {@code q} quantile of {@code sorted}, NaN when there is no sample. */
        static double percentile(double[] sorted, double q) {
            return sorted.length == 0 ? Double.NaN
                    : sorted[Math.min(sorted.length - 1, (int) Math.ceil(q * sorted.length) - 1)];
        }

        /** The samples of {@code millis} that are latencies (not NaN), sorted. */
        static double[] latencies(double[] millis) {
            return Arrays.stream(millis).filter(m -> !Double.isNaN(m)).sorted().toArray();
        }
    }

    /** Time for a fresh follower to register its watches and look at every log once before it is measured. */
    static final long SETTLE_MILLIS = 300;
    /**
     * Before the idle phase: at least this long, and until the JIT compiler has been quiet this long (at most 20 s),
     * so that compiling what the catch-up ran is not counted as the cost of idle logs.
     */
    private static final long IDLE_SETTLE_MILLIS = 1000;

    private final FleetSetup setup;
    private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    private final OperatingSystemMXBean os = ManagementFactory.getPlatformMXBean(OperatingSystemMXBean.class);
    private final byte[] before;
    private final byte[] trigger;
    private final long beforeRecords;
    private final RobotPace pace;
    /** How long the robot-pace phase and the idle phase run. */
    private final long phaseNanos;

    private FleetBench(Abstraction abstraction, ModelSet models, long pollMicros, boolean polling, double seconds,
                       Path dir) throws Exception {
        this.phaseNanos = (long) (seconds * 1e9);
        this.setup = new FleetSetup(abstraction, models, pollMicros * 1000, polling, dir);
        String[] parts = LatencyBench.warningRun(abstraction, models, dir);
        this.before = parts[0].getBytes(StandardCharsets.UTF_8);
        this.trigger = parts[1].getBytes(StandardCharsets.UTF_8);
        this.beforeRecords = LatencyBench.countRecords(before);
        this.pace = new RobotPace(setup);
    }

    /**
     * Measures fleets of each size in {@code sizes}, about {@code samples} latencies each.
     *
     * @param pollMicros the pause between two polls of a log that is polled
     * @param polling    poll every log ({@code watch --polling}) instead of waiting for notifications
     * @param seconds    how long the robot-pace and the idle phase run per size
     */
    static List<Result> run(Abstraction abstraction, ModelSet models, List<Integer> sizes, int samples, long pollMicros,
                            boolean polling, double seconds, Path dir) throws Exception {
        FleetBench b = new FleetBench(abstraction, models, pollMicros, polling, seconds, dir);
        b.measure(Math.min(10, sizes.get(sizes.size() - 1)), Math.min(20, samples), false); // warm-up: JIT, cache
        List<Result> out = new ArrayList<>();
        for (int n : sizes) {
            out.add(b.measure(n, samples, true));
        }
        return out;
    }

    /**
     * Measures one fleet size; {@code full} false for the warm-up, which runs every phase but the idle one, shorter.
     */
    private Result measure(int logs, int samples, boolean full) throws Exception {
        int rounds = Math.max(1, (samples + logs - 1) / logs);
        double[] millis = new double[rounds * logs];
        long catchUpCpu = 0;
        long caughtUp = 0;
        double[] idleCore = {0, 0};
        for (int r = 0; r < rounds; r++) {
            try (ScratchDir round = setup.scratch("predmon-fleet")) {
                List<Path> files = new ArrayList<>();
                for (int i = 0; i < logs; i++) {
                    files.add(Files.write(round.resolve("robot-" + i + ".log"), before));
                }
                AtomicLongArray warnedAt = new AtomicLongArray(logs);
                Map<WatchedLog, Integer> index = new HashMap<>();
                try (Fleet fleet = setup.fleet((log, e) -> {
                    if (e instanceof MonitorEvent.Warning) {
                        warnedAt.set(index.get(log), System.nanoTime());
                    }
                })) {
                    for (Path f : files) {
                        index.put(fleet.add(f), index.size());
                    }
                    long cpu = threads.getCurrentThreadCpuTime();
                    while (fleet.logs().stream().anyMatch(l -> l.monitor().pipeline().records() < beforeRecords)) {
                        fleet.poll();
                    }
                    catchUpCpu += threads.getCurrentThreadCpuTime() - cpu;
                    caughtUp += logs * beforeRecords;
                    // Reading up to 1000 logs at once leaves garbage that watch's steady state does not make; on a
                    // busy 2-core machine its collection paused the process for 20 to 160 ms in the phases below.
                    System.gc();
                    try (Following following = setup.follow(fleet, round.path())) {
                        if (r == 0 && full) {
                            idleCore = idle(following);
                        } else {
                            Thread.sleep(SETTLE_MILLIS);
                        }
                        latencies(files, trigger, warnedAt, new Random(r), millis, r * logs);
                    }
                }
            }
        }
        RobotPace.Load load = pace.measure(logs, full ? phaseNanos : phaseNanos / 5, pacedSamples(logs, samples),
                before, trigger, beforeRecords);
        return new Result(logs, (double) catchUpCpu / caughtUp, idleCore[0], idleCore[1], pace.rate(), load,
                Result.latencies(millis), millis.length - Result.latencies(millis).length);
    }

    /** Warnings measured at robot pace: one per log of a tenth of the fleet more, at most {@code samples}. */
    static int pacedSamples(int logs, int samples) {
        return Math.max(1, Math.min(samples, logs / 10));
    }

    /**
     * Waits at least {@link #IDLE_SETTLE_MILLIS}, and until the JIT compiler has been quiet that long (at most 20 s),
     * so that compiling what ran before is not counted as the cost of what is measured next.
     */
    static void compilerQuiet() throws InterruptedException {
        CompilationMXBean jit = ManagementFactory.getCompilationMXBean();
        long settled = System.nanoTime() + 20_000_000_000L;
        long compiled;
        do {
            compiled = jit.getTotalCompilationTime();
            Thread.sleep(IDLE_SETTLE_MILLIS);
        } while (jit.getTotalCompilationTime() != compiled && System.nanoTime() < settled);
    }

    /** {share of a core of the process, of the following thread} while following logs that do not grow. */
    private double[] idle(Following following) throws Exception {
        compilerQuiet();
        long cpu = os.getProcessCpuTime();
        long loop = threads.getThreadCpuTime(following.thread().getId());
        long start = System.nanoTime();
        Thread.sleep(phaseNanos / 1_000_000);
        double wall = System.nanoTime() - start;
        return new double[] {(os.getProcessCpuTime() - cpu) / wall,
                (threads.getThreadCpuTime(following.thread().getId()) - loop) / wall};
    }

    /**
     * Appends {@code trigger}, the warning's record, to each of {@code files} once, in random order, 1 to 3 ms apart, and waits for
     * their warnings: each log's time from the start of its write to its warning goes to {@code into} from {@code at}
     * (NaN for a log that had warned before).
     */
    static void latencies(List<Path> files, byte[] trigger, AtomicLongArray warnedAt, Random random, double[] into, int at)
            throws Exception {
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < files.size(); i++) {
            order.add(i);
        }
        Collections.shuffle(order, random);
        long[] writtenAt = new long[files.size()];
        for (int i : order) {
            try (OutputStream out = Files.newOutputStream(files.get(i), StandardOpenOption.APPEND)) {
                // Before the write: on a busy machine the threads the write wakes can run first and warn before
                // this thread reads the clock again, which made such samples 0.
                writtenAt[i] = System.nanoTime();
                out.write(trigger);
            }
            LockSupport.parkNanos(1_000_000L + random.nextInt(2_000_000));
        }
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (IntStream.range(0, files.size()).anyMatch(i -> warnedAt.get(i) == 0) && System.nanoTime() < deadline) {
            Thread.sleep(1);
        }
        for (int i = 0; i < files.size(); i++) {
            if (warnedAt.get(i) == 0) {
                throw new IllegalStateException("log " + i + " of " + files.size() + ": no warning within 60 s");
            }
            // A log that warned before the record was written gives no latency (NaN), and is counted apart.
            long after = warnedAt.get(i) - writtenAt[i];
            into[at + i] = after < 0 ? Double.NaN : after / 1e6;
        }
    }
}
