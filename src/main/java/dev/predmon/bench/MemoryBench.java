package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.parse.LogParser;
import dev.predmon.simulate.Scenario;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;

/**
 * The monitor on an endless log: lines of simulated runs are generated on the fly (a pool of runs cycled; no
 * file, nothing accumulated) and pushed through {@code watch}'s parser and {@link PredictiveMonitor}, restarted
 * at each run boundary as a rotated log restarts it. Every {@code chunk} records it notes the CPU time this
 * thread spent per record and the heap in use after a GC: both must stay flat as the log grows. Meant to run
 * under {@code -Xmx64m}.
 */
final class MemoryBench {

    /**
     * @param records    records at each checkpoint
     * @param cpuNanos   CPU nanoseconds per record over the chunk ending there
     * @param heapMb     heap in use after a GC there, in MB
     * @param maxHeapMb  the JVM's -Xmx, in MB
     */
    // Arrays: one value per checkpoint; a result is printed, never compared or hashed.
    @SuppressWarnings("ArrayRecordComponent")
    record Result(long[] records, double[] cpuNanos, double[] heapMb, double maxHeapMb) {
    }

    private MemoryBench() {
    }

    static Result run(Abstraction abstraction, ModelSet models, long total, int checkpoints) {
        List<String[]> pool = new ArrayList<>();
        Scenario[] scenarios = Scenario.values();
        for (int i = 0; i < 6; i++) {
            pool.add(BenchData.text(scenarios[i % scenarios.length], 30_000 + i).split("\n"));
        }
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, 0, e -> {
        });
        long[] count = {0};
        LogParser parser = new LogParser(r -> {
            count[0]++;
            monitor.accept(r);
        }, p -> {
        });
        long chunk = Math.max(1, total / checkpoints);
        long[] at = new long[checkpoints];
        double[] cpu = new double[checkpoints];
        double[] heap = new double[checkpoints];
        int k = 0;
        long next = chunk;
        long cpuStart = threads.getCurrentThreadCpuTime();
        int run = 0;
        outer:
        while (true) {
            for (String line : pool.get(run++ % pool.size())) {
                parser.acceptLine(line);
                if (count[0] >= next) {
                    long now = threads.getCurrentThreadCpuTime();
                    at[k] = count[0];
                    cpu[k] = (double) (now - cpuStart) / chunk;
                    heap[k] = usedAfterGc();
                    k++;
                    next += chunk;
                    if (k == checkpoints) {
                        break outer;
                    }
                    cpuStart = threads.getCurrentThreadCpuTime();
                }
            }
            parser.endOfInput();
            parser.reset();
            monitor.restart("next run");
        }
        return new Result(at, cpu, heap, Runtime.getRuntime().maxMemory() / 1e6);
    }

    private static double usedAfterGc() {
        System.gc();
        Runtime rt = Runtime.getRuntime();
        return (rt.totalMemory() - rt.freeMemory()) / 1e6;
    }
}
