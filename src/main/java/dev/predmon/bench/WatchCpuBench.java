package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.LogWatcher;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.simulate.Scenario;

import java.io.OutputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;

/**
 * CPU per record of a following {@code watch}: a {@link LogWatcher} with a {@link PredictiveMonitor} runs {@code
 * watch}'s loop on a thread of its own (a poll, and the poll pause when nothing was appended), while a writer thread
 * appends simulated runs to its log, one run at a time, each once the watcher has taken the run before. The figure is
 * the following thread's own CPU time ({@link ThreadMXBean#getThreadCpuTime}) over the records it took: reading,
 * parsing, abstracting, compacting, matching, every property's check and the forecast, and its empty polls between
 * two appends. The process's CPU time over the same records is given beside it (it adds the writer, the garbage
 * collector and the compiler). A first share of the records, not measured, warms the compiler up.
 */
final class WatchCpuBench {

    /**
     * @param records      records the following thread took while measured
     * @param threadNanos  its CPU time per record, ns
     * @param processNanos the whole process's CPU time per record over the same span, ns
     * @param seconds      the measured span's wall time
     */
    record Result(long records, double threadNanos, double processNanos, double seconds) {
    }

    /** One unmeasured record per this many measured ones comes first: the compiler is still at work before. */
    private static final int WARM_UP_SHARE = 2;

    private WatchCpuBench() {
    }

    static Result run(Abstraction abstraction, ModelSet models, long records, long pollMicros, Path dir)
            throws Exception {
        List<byte[]> pool = new ArrayList<>();
        List<Long> counts = new ArrayList<>();
        Scenario[] scenarios = Scenario.values();
        for (int i = 0; i < 6; i++) {
            byte[] run = BenchData.text(scenarios[i % scenarios.length], 40_000 + i).getBytes(StandardCharsets.UTF_8);
            pool.add(run);
            counts.add(LatencyBench.countRecords(run));
        }
        Path file = Files.createTempFile(dir, "predmon-cpu", ".log");
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        AtomicLong taken = new AtomicLong();
        AtomicBoolean stop = new AtomicBoolean();
        AtomicReference<Throwable> failed = new AtomicReference<>();
        PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, 0, e -> {
        });
        Thread follower = new Thread(() -> {
            try (LogWatcher w = LogWatcher.withRecords(file, monitor, p -> {
            }, r -> taken.incrementAndGet())) {
                while (!stop.get()) {
                    if (!w.poll()) {
                        LockSupport.parkNanos(pollMicros * 1000);
                    }
                }
            } catch (Throwable t) {
                failed.set(t);
            }
        }, "predmon-bench-watch");
        follower.start();
        try (OutputStream out = Files.newOutputStream(file)) {
            long warmUp = records / WARM_UP_SHARE;
            long written = append(out, pool, counts, 0, warmUp, taken, failed);
            long threadStart = threads.getThreadCpuTime(follower.getId());
            long processStart = os.getProcessCpuTime();
            long wallStart = System.nanoTime();
            long measured = append(out, pool, counts, written, written + records, taken, failed) - written;
            double threadNanos = threads.getThreadCpuTime(follower.getId()) - threadStart;
            double processNanos = os.getProcessCpuTime() - processStart;
            double seconds = (System.nanoTime() - wallStart) / 1e9;
            return new Result(measured, threadNanos / measured, processNanos / measured, seconds);
        } finally {
            stop.set(true);
            follower.join();
            Files.deleteIfExists(file);
        }
    }

    /**
     * Appends runs of the pool until at least {@code until} records are written in all, each run once the watcher
     * has taken every record before it.
     *
     * @return the records written in all
     */
    private static long append(OutputStream out, List<byte[]> pool, List<Long> counts, long written, long until,
                               AtomicLong taken, AtomicReference<Throwable> failed) throws Exception {
        int next = 0;
        while (written < until) {
            int k = next++ % pool.size();
            out.write(pool.get(k));
            out.flush();
            written += counts.get(k);
            long deadline = System.nanoTime() + 30_000_000_000L;
            while (taken.get() < written) {
                if (failed.get() != null) {
                    throw new IllegalStateException("following failed", failed.get());
                }
                if (System.nanoTime() > deadline) {
                    throw new IllegalStateException("the watcher took " + taken.get() + " of " + written
                            + " records within 30 s");
                }
                LockSupport.parkNanos(50_000);
            }
        }
        return written;
    }
}
