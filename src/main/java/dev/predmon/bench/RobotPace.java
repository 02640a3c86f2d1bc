package dev.predmon.bench;

import com.sun.management.OperatingSystemMXBean;
import dev.predmon.monitor.Fleet;
import dev.predmon.parse.LogRecord;
import dev.predmon.simulate.Scenario;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * The robot-pace phase of {@link FleetBench}: while a fleet follows its logs, a writer thread appends to every log at
 * the simulated robot's own pace (records per second of its log's clock), each log from its own point of a depleted
 * run, as robots do not start together. It measures the process's CPU time less the writer's: the share of a core
 * and the CPU per record read.
 */
final class RobotPace {

    /**
     * @param core           share of one core (0..1) the process spent, the writer left out
     * @param nanosPerRecord CPU ns per record read
     * @param readRate       records per second read per log: below the robot's pace when the writer fell behind
     */
    record Load(double core, double nanosPerRecord, double readRate) {
    }

    private final FleetSetup setup;
    private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    private final OperatingSystemMXBean os = ManagementFactory.getPlatformMXBean(OperatingSystemMXBean.class);
    /** The depleted run every log repeats, record by record. */
    private final List<byte[]> run;
    /** Records per second of the run's own clock. */
    private final double rate;

    RobotPace(FleetSetup setup) {
        this.setup = setup;
        String text = BenchData.text(Scenario.DEPLETED, 20_001);
        this.run = records(text);
        List<LogRecord> parsed = BenchData.records(text);
        this.rate = parsed.size() / (parsed.get(parsed.size() - 1).time() - parsed.get(0).time());
    }

    /** Records per second appended to each log. */
    double rate() {
        return rate;
    }

    /** The load of following {@code logs} logs growing at the robot's pace for {@code nanos}. */
    Load measure(int logs, long nanos) throws Exception {
        try (ScratchDir round = setup.scratch("predmon-fleet-pace"); Fleet fleet = setup.fleet((log, e) -> { })) {
            List<Path> files = new ArrayList<>();
            for (int i = 0; i < logs; i++) {
                Path f = Files.createFile(round.resolve("robot-" + i + ".log"));
                files.add(f);
                fleet.add(f);
            }
            int[] cursor = new int[logs];
            for (int i = 0; i < logs; i++) {
                cursor[i] = (int) ((long) i * run.size() / Math.max(1, logs));
            }
            AtomicLong writerCpu = new AtomicLong();
            long used;
            double wall;
            try (Following following = setup.follow(fleet, round.path())) {
                Thread.sleep(FleetBench.SETTLE_MILLIS);
                long start = System.nanoTime();
                Thread writer = new Thread(() -> {
                    write(files, cursor, start, nanos);
                    writerCpu.set(threads.getCurrentThreadCpuTime());
                }, "predmon-bench-pace");
                long cpu = os.getProcessCpuTime();
                writer.start();
                writer.join();
                Thread.sleep(50); // the last appends read
                used = os.getProcessCpuTime() - cpu - writerCpu.get();
                wall = System.nanoTime() - start;
            }
            long records = fleet.logs().stream().mapToLong(l -> l.monitor().pipeline().records()).sum();
            return new Load(used / wall, (double) used / Math.max(1, records), records / (wall / 1e9) / logs);
        }
    }

    /**
     * Appends to every log at the robot's pace for {@code nanos}, looking every 5 ms. Each log is opened for its
     * append and closed after it, as a logger that reopens its file would: a fleet of 10,000 logs is not 10,000 open
     * writers in the bench's own process.
     */
    private void write(List<Path> files, int[] cursor, long start, long nanos) {
        long written = 0;
        ByteArrayOutputStream chunk = new ByteArrayOutputStream();
        while (System.nanoTime() - start < nanos) {
            long due = (long) ((System.nanoTime() - start) / 1e9 * rate);
            try {
                if (written < due) {
                    for (int i = 0; i < files.size(); i++) {
                        chunk.reset();
                        for (long w = written; w < due; w++) {
                            chunk.write(run.get(cursor[i]));
                            cursor[i] = (cursor[i] + 1) % run.size();
                        }
                        try (OutputStream out = Files.newOutputStream(files.get(i), StandardOpenOption.APPEND)) {
                            chunk.writeTo(out);
                        }
                    }
                    written = due;
                }
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            LockSupport.parkNanos(5_000_000L);
        }
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
}
