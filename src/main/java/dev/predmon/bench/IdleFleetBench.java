package dev.predmon.bench;

import com.sun.management.OperatingSystemMXBean;
import com.sun.management.UnixOperatingSystemMXBean;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.simulate.Scenario;

import java.lang.management.CompilationMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The idle cost of a large fleet ({@code --fleet-idle-logs}, 10,000 by default): that many logs of a few records each
 * in one directory, followed as {@code watch --log DIR} follows them, then left alone. It reports the share of a core
 * the process and the following thread use, the heap in use after a collection, and the descriptors the process
 * holds against its limit: beyond half of what is free, the fleet closes idle logs' files
 * ({@code watch} says so) and reopens them when they change. No writer is held open per log.
 *
 * @param logs        logs followed
 * @param core        share of one core of the whole process while idle
 * @param loopCore    share of one core of the following thread
 * @param heapMb      heap in use after a collection, following them
 * @param baseHeapMb  heap in use after a collection before the fleet was made
 * @param descriptors descriptors the process held while following, or -1 where that cannot be told
 * @param baseFds     descriptors before the fleet was made
 * @param maxFds      the process's descriptor limit, or -1
 */
record IdleFleetBench(int logs, double core, double loopCore, double heapMb, double baseHeapMb, long descriptors,
                      long baseFds, long maxFds) {

    /** The first records of a depleted run: each log's content. */
    private static final int RECORDS = 12;

    static IdleFleetBench run(FleetSetup setup, int logs, double seconds) throws Exception {
        OperatingSystemMXBean os = ManagementFactory.getPlatformMXBean(OperatingSystemMXBean.class);
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        byte[] head = head(BenchData.text(Scenario.DEPLETED, 20_002));
        try (ScratchDir round = setup.scratch("predmon-fleet-idle")) {
            List<Path> files = new ArrayList<>();
            for (int i = 0; i < logs; i++) {
                files.add(Files.write(round.resolve("robot-" + i + ".log"), head));
            }
            System.gc();
            double baseHeap = memory.getHeapMemoryUsage().getUsed() / 1e6;
            long baseFds = fds(os);
            try (Fleet fleet = setup.fleet((log, e) -> { })) {
                List<WatchedLog> watched = files.stream().map(fleet::add).toList(); // before the following thread
                Following following = setup.follow(fleet, round.path());
                try (following) {
                    return measure(following, watched, logs, seconds, baseHeap, baseFds);
                }
            }
        }
    }

    private static IdleFleetBench measure(Following following, List<WatchedLog> watched, int logs, double seconds,
                                          double baseHeap, long baseFds) throws Exception {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        OperatingSystemMXBean os = ManagementFactory.getPlatformMXBean(OperatingSystemMXBean.class);
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (watched.stream().anyMatch(l -> l.monitor().records() == 0)) {
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("the fleet did not read its " + logs + " logs within 120 s");
            }
            Thread.sleep(50);
        }
        settle();
        long cpu = os.getProcessCpuTime();
        long loop = threads.getThreadCpuTime(following.thread().getId());
        long start = System.nanoTime();
        Thread.sleep((long) (seconds * 1000));
        double wall = System.nanoTime() - start;
        double core = (os.getProcessCpuTime() - cpu) / wall;
        double loopCore = (threads.getThreadCpuTime(following.thread().getId()) - loop) / wall;
        long held = fds(os);
        System.gc();
        double heap = memory.getHeapMemoryUsage().getUsed() / 1e6;
        long max = os instanceof UnixOperatingSystemMXBean u ? u.getMaxFileDescriptorCount() : -1;
        return new IdleFleetBench(logs, core, loopCore, heap, baseHeap, held, baseFds, max);
    }

    /** Waits until the compiler has been quiet for a second (at most 20 s), so that its work is not counted. */
    private static void settle() throws InterruptedException {
        CompilationMXBean jit = ManagementFactory.getCompilationMXBean();
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        long compiled;
        do {
            compiled = jit.getTotalCompilationTime();
            Thread.sleep(1000);
        } while (jit.getTotalCompilationTime() != compiled && System.nanoTime() < until);
    }

    private static long fds(OperatingSystemMXBean os) {
        return os instanceof UnixOperatingSystemMXBean u ? u.getOpenFileDescriptorCount() : -1;
    }

    /** The first {@value #RECORDS} records of {@code text}. */
    private static byte[] head(String text) {
        StringBuilder out = new StringBuilder();
        int records = 0;
        for (String line : text.split("\n", -1)) {
            if (!line.isEmpty() && Character.isDigit(line.charAt(0)) && ++records > RECORDS) {
                break;
            }
            out.append(line).append('\n');
        }
        return out.toString().getBytes(StandardCharsets.UTF_8);
    }

    /** Heap per log beyond what was in use before, in KB. */
    double kbPerLog() {
        return (heapMb - baseHeapMb) * 1000 / logs;
    }
}
