package dev.predmon.bench;

import com.sun.management.OperatingSystemMXBean;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.parse.LogRecord;
import dev.predmon.simulate.Scenario;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.locks.LockSupport;

/**
 * The robot-pace phase of {@link FleetBench}: while a fleet follows its logs, another process ({@link PaceWriter})
 * appends to every log at the simulated robot's own pace (records per second of its log's clock), each log from its
 * own point of a depleted run, as robots do not start together, the writes spread evenly over time. Meanwhile the
 * warning record is appended to a few more logs of the same directory, each holding a depleted run up to it, one by
 * one: the time from each append to its warning is the latency at robot pace. It measures this process's CPU time
 * (the writer's is its own process's): the share of a core and the CPU per record read.
 */
final class RobotPace {

    /**
     * @param core           share of one core (0..1) this process spent
     * @param nanosPerRecord CPU ns per record read
     * @param writtenRate    records per second the writer appended per log: below the robot's pace when it lagged
     * @param readRate       records per second read per log
     * @param millis         append-to-warning latencies at robot pace, sorted
     * @param writerCore     share of one core the writer process spent
     * @param early          logs that warned before the warning's record was written: no sample
     */
    // An array: sorted samples for percentiles; a result is printed, never compared or hashed.
    @SuppressWarnings("ArrayRecordComponent")
    record Load(double core, double nanosPerRecord, double writtenRate, double readRate, double[] millis,
                double writerCore, int early) {
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

    /**
     * The load of following {@code logs} logs growing at the robot's pace for {@code nanos} (longer when the
     * {@code samples} warnings take longer), measured over its last two thirds once the compiler is quiet, and the
     * latency of {@code samples} warnings meanwhile: {@code before}
     * is a depleted run up to {@code trigger}, the record that raises the warning.
     */
    Load measure(int logs, long nanos, int samples, byte[] before, byte[] trigger, long beforeRecords)
            throws Exception {
        try (ScratchDir scratch = setup.scratch("predmon-fleet-run"); ScratchDir round = setup.scratch("predmon-fleet-pace")) {
            AtomicLongArray warnedAt = new AtomicLongArray(samples);
            Map<WatchedLog, Integer> index = new HashMap<>();
            try (Fleet fleet = setup.fleet((log, e) -> {
                Integer i = index.get(log);
                if (i != null && e instanceof MonitorEvent.Warning) {
                    warnedAt.set(i, System.nanoTime());
                }
            })) {
                List<Path> warning = new ArrayList<>();
                for (int i = 0; i < samples; i++) {
                    Path f = Files.write(round.resolve("warn-" + i + ".log"), before);
                    warning.add(f);
                    index.put(fleet.add(f), i);
                }
                for (int i = 0; i < logs; i++) {
                    fleet.add(Files.createFile(round.resolve("robot-" + i + ".log")));
                }
                while (fleet.logs().stream().anyMatch(l -> index.containsKey(l) && l.monitor().pipeline().records() < beforeRecords)) {
                    fleet.poll();
                }
                Path runFile = scratch.resolve("run.records");
                try (OutputStream out = Files.newOutputStream(runFile)) {
                    for (byte[] r : run) {
                        out.write(r);
                        out.write(PaceWriter.SEPARATOR.getBytes(StandardCharsets.UTF_8));
                    }
                }
                System.gc(); // the catch-up's garbage is not the robot pace's
                double[] millis = new double[samples];
                long used;
                long start;
                long readBefore;
                long records;
                double wall;
                String[] wrote;
                try (Following following = setup.follow(fleet, round.path());
                     Writer writer = new Writer(runFile, round.path(), logs, rate, scratch.resolve("writer.err"))) {
                    Thread.sleep(FleetBench.SETTLE_MILLIS);
                    writer.go();
                    // The first third: the compiler meets the paths of whole runs, which the catch-up did not take;
                    // then until it has been quiet for a second (at most 20 s more).
                    LockSupport.parkNanos(nanos / 3);
                    FleetBench.compilerQuiet();
                    long cpu = os.getProcessCpuTime();
                    long mine = threads.getCurrentThreadCpuTime();
                    readBefore = paced(fleet, index);
                    start = System.nanoTime();
                    LockSupport.parkNanos(Math.min(nanos / 6, 1_000_000_000L)); // the fleet at pace first
                    FleetBench.latencies(warning, trigger, warnedAt, new Random(logs), millis, 0);
                    LockSupport.parkNanos(start + nanos * 2 / 3 - System.nanoTime());
                    used = os.getProcessCpuTime() - cpu - (threads.getCurrentThreadCpuTime() - mine);
                    wall = System.nanoTime() - start;
                    records = paced(fleet, index) - readBefore;
                    wrote = writer.stop();
                }
                double writtenRate = Long.parseLong(wrote[1]) / (Long.parseLong(wrote[2]) / 1e9) / logs;
                return new Load(used / wall, (double) used / Math.max(1, records), writtenRate,
                        records / (wall / 1e9) / logs, FleetBench.Result.latencies(millis),
                        Double.parseDouble(wrote[3]) / Double.parseDouble(wrote[2]),
                        samples - FleetBench.Result.latencies(millis).length);
            }
        }
    }

    /** Records read so far from the logs growing at robot pace (not the warning logs of {@code index}). */
    private static long paced(Fleet fleet, Map<WatchedLog, Integer> index) {
        return fleet.logs().stream().filter(l -> !index.containsKey(l)).mapToLong(l -> l.monitor().pipeline().records())
                .sum();
    }

    /** The {@link PaceWriter} process: ready once started, writing between {@link #go} and {@link #stop}. */
    private static final class Writer implements AutoCloseable {

        private final Process process;
        private final BufferedReader out;
        private final Path err;

        Writer(Path runFile, Path dir, int logs, double rate, Path err) throws IOException {
            this.err = err;
            String java = ProcessHandle.current().info().command().orElse("java");
            process = new ProcessBuilder(java, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-Xmx256m",
                    "-cp", System.getProperty("java.class.path"), PaceWriter.class.getName(), runFile.toString(),
                    dir.toString(), Integer.toString(logs), Double.toString(rate))
                    .redirectError(err.toFile()).start();
            out = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
            expect("ready");
        }

        void go() throws IOException {
            process.getOutputStream().write("go\n".getBytes(StandardCharsets.UTF_8));
            process.getOutputStream().flush();
        }

        /** Stops the writer: {"wrote", records, nanos, its CPU nanos}. */
        String[] stop() throws IOException {
            process.getOutputStream().close();
            return expect("wrote").split(" ");
        }

        private String expect(String word) throws IOException {
            String line = out.readLine();
            if (line == null || !line.startsWith(word)) {
                throw new IOException("the bench's writer process failed: " + line + " "
                        + (Files.exists(err) ? Files.readString(err) : ""));
            }
            return line;
        }

        @Override
        public void close() throws InterruptedException {
            process.destroy();
            process.waitFor();
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
