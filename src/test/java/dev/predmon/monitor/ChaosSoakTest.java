package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.parse.LogFollower;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * Chaos soak: {@value #LOGS} robots' logs in one watched directory, each appended at {@value #SPEED}x robot pace with
 * simulated runs from a pool whose verdicts are known (each run watched alone), and between runs renamed (also twice
 * before the logger reopens, the middle file left empty), renamed while the logger goes on writing the renamed file
 * (also after a pause past the turn to the new file, which another program wrote a line to),
 * copytruncated, truncated, deleted, replaced by a FIFO or by a directory. Every warning and violation that watching
 * each run alone gives must arrive, and once the logs are gone the process holds the descriptors it held before.
 */
class ChaosSoakTest {

    private static final int LOGS = 12;
    private static final int SPEED = 8;
    private static final long CHAOS_NANOS = TimeUnit.SECONDS.toNanos(40);
    private static final Abstraction ABSTRACTION = AbstractionFiles.defaults();
    private static final Path FDS = Path.of("/proc/self/fd");

    /** What is done to a log before its next run is written. */
    private enum Chaos {
        RENAME, RENAME_TWICE_EMPTY, RENAME_WHILE_WRITTEN, RENAME_PAUSED_WRITTEN, COPYTRUNCATE, TRUNCATE, DELETE, FIFO,
        DIRECTORY
    }

    /** A run of the pool: its text, its records, and how many warnings and violations it gives watched alone. */
    private record PoolRun(String text, long records, int warnings, int violations) {
    }

    @TempDir
    Path dir;

    private final Map<String, AtomicLong> warnings = new ConcurrentHashMap<>();
    private final Map<String, AtomicLong> violations = new ConcurrentHashMap<>();
    private final Map<String, AtomicLong> records = new ConcurrentHashMap<>();

    @Test
    @Timeout(150)
    void everyWarningAndViolationArrivesThroughRotationsAndTheDescriptorsComeBack() throws Exception {
        assumeTrue(Files.isDirectory(FDS), "no /proc/self/fd here");
        ModelSet models = ModelStore.read(Path.of("models"), ABSTRACTION);
        List<PoolRun> pool = pool(models);
        assertTrue(pool.stream().anyMatch(r -> r.warnings() > 0) && pool.stream().anyMatch(r -> r.warnings() == 0),
                "the pool holds runs that warn and runs that do not");
        Path robots = Files.createDirectories(dir.resolve("robots"));
        Fleet fleet = new Fleet(models, ABSTRACTION, 0, ABSTRACTION.confirm(), new FleetListener() {
            @Override
            public void event(WatchedLog log, MonitorEvent e) {
                if (e instanceof MonitorEvent.Warning) {
                    count(warnings, log);
                } else if (e instanceof MonitorEvent.Violation) {
                    count(violations, log);
                }
            }

            @Override
            public void record(WatchedLog log, dev.predmon.parse.LogRecord r) {
                count(records, log);
            }
        });
        // a file gone from its path is let go 3 s after it last grew: past the paused logger's 1.5 s
        fleet.limits(Duration.ofSeconds(3), Integer.MAX_VALUE);
        AtomicReference<Throwable> failed = new AtomicReference<>();
        Thread following = new Thread(() -> {
            try {
                fleet.follow(new LogSources(List.of(robots)), TimeUnit.MILLISECONDS.toNanos(2), false);
            } catch (Throwable t) {
                failed.set(t);
            }
        }, "chaos-fleet");
        long start;
        Map<String, int[]> expected = new TreeMap<>(); // per log: warnings, violations
        Map<Chaos, AtomicLong> done = new ConcurrentHashMap<>();
        long began = System.nanoTime();
        try (fleet) {
            following.start();
            Thread.sleep(500);
            start = descriptors();
            List<Thread> writers = new ArrayList<>();
            List<Throwable> writerFailures = new ArrayList<>();
            for (int i = 0; i < LOGS; i++) {
                String name = "robot-" + i + ".log";
                int[] sum = new int[2];
                expected.put(name, sum);
                int index = i;
                Thread w = new Thread(() -> {
                    try {
                        robot(robots.resolve(name), index, pool, sum, done);
                    } catch (Throwable t) {
                        synchronized (writerFailures) {
                            writerFailures.add(t);
                        }
                    }
                }, "robot-" + i);
                writers.add(w);
                w.start();
            }
            for (Thread w : writers) {
                w.join();
            }
            assertEquals(List.of(), writerFailures);
            await(() -> expected.entrySet().stream().allMatch(e -> got(warnings, e.getKey()) >= e.getValue()[0]
                    && got(violations, e.getKey()) >= e.getValue()[1]), "every warning and violation", 30);
            try (Stream<Path> left = Files.list(robots)) {
                for (Path p : left.toList()) {
                    Files.delete(p);
                }
            }
            await(() -> descriptors() <= start, "the descriptors of the deleted logs: " + descriptors() + " vs " + start
                    + " at the start", 20);
            assertEquals(null, failed.get());
        } finally {
            following.interrupt();
            following.join(10_000);
        }
        long runs = expected.size();
        int wantWarnings = expected.values().stream().mapToInt(s -> s[0]).sum();
        int wantViolations = expected.values().stream().mapToInt(s -> s[1]).sum();
        long gotWarnings = expected.keySet().stream().mapToLong(n -> got(warnings, n)).sum();
        long gotViolations = expected.keySet().stream().mapToLong(n -> got(violations, n)).sum();
        System.out.printf(Locale.ROOT, "chaos soak: %d logs, %s, warnings %d of %d, violations %d of %d, %.1f s%n",
                runs, done, gotWarnings, wantWarnings, gotViolations, wantViolations,
                (System.nanoTime() - began) / 1e9);
        for (Map.Entry<String, int[]> e : expected.entrySet()) {
            assertEquals(e.getValue()[0], got(warnings, e.getKey()), e.getKey() + ": warnings");
            assertEquals(e.getValue()[1], got(violations, e.getKey()), e.getKey() + ": violations");
        }
        assertTrue(done.keySet().containsAll(List.of(Chaos.values())), "every kind of chaos happened: " + done);
    }

    /** One robot: runs from the pool, one after another, with chaos before each but the first. */
    private void robot(Path log, int index, List<PoolRun> pool, int[] sum, Map<Chaos, AtomicLong> done)
            throws Exception {
        Random random = new Random(index);
        Chaos[] kinds = Chaos.values();
        long end = System.nanoTime() + CHAOS_NANOS;
        String name = log.getFileName().toString();
        for (int n = 0; System.nanoTime() < end || n < 2; n++) {
            PoolRun run = pool.get(random.nextInt(pool.size()));
            Chaos chaos = n == 0 ? null : kinds[(index + n) % kinds.length];
            if (chaos != null) {
                apply(chaos, log, name, n);
                // (the paused writer is a way of writing, counted below; applied before a run it is a rename)
                done.computeIfAbsent(chaos == Chaos.RENAME_PAUSED_WRITTEN ? Chaos.RENAME : chaos,
                        k -> new AtomicLong()).incrementAndGet();
            }
            long before = got(records, name);
            if (chaos == null || n % 3 != 0 || !Files.exists(log)) {
                write(log, run.text(), null, false);
            } else { // logrotate's create while the logger writes: it goes on in the renamed file
                boolean paused = (index + n) % 2 == 0; // and pauses first, past the turn to the new file
                write(log, run.text(), log.resolveSibling(name + ".w" + n), paused);
                done.computeIfAbsent(paused ? Chaos.RENAME_PAUSED_WRITTEN : Chaos.RENAME_WHILE_WRITTEN,
                        k -> new AtomicLong()).incrementAndGet();
            }
            sum[0] += run.warnings();
            sum[1] += run.violations();
            // copytruncate and truncate lose what was not read before: what no follower of a path can see
            await(() -> got(records, name) >= before + run.records(), name + ": the run is read", 30);
        }
    }

    private static void apply(Chaos chaos, Path log, String name, int n) throws Exception {
        Path rotated = log.resolveSibling(name + "." + n);
        switch (chaos) {
            case RENAME, RENAME_PAUSED_WRITTEN -> {
                Files.move(log, rotated);
                Files.writeString(log, "");
            }
            case RENAME_TWICE_EMPTY -> {
                Files.move(log, rotated);
                Files.writeString(log, "");
                Thread.sleep(100);
                Files.move(log, log.resolveSibling(name + "." + n + "b"));
                Files.writeString(log, "");
            }
            case RENAME_WHILE_WRITTEN -> {
                Files.move(log, rotated);
            }
            case COPYTRUNCATE -> {
                Files.copy(log, rotated, StandardCopyOption.REPLACE_EXISTING);
                truncate(log);
            }
            case TRUNCATE -> truncate(log);
            case DELETE -> Files.delete(log);
            case FIFO -> {
                Files.delete(log);
                if (new ProcessBuilder("mkfifo", log.toString()).inheritIO().start().waitFor() == 0) {
                    Thread.sleep(200);
                    Files.delete(log);
                }
            }
            case DIRECTORY -> {
                Files.delete(log);
                Files.createDirectory(log);
                Thread.sleep(200);
                Files.delete(log);
            }
        }
    }

    private static void truncate(Path log) throws IOException {
        try (FileChannel c = FileChannel.open(log, StandardOpenOption.WRITE)) {
            c.truncate(0);
        }
    }

    /**
     * Appends {@code text} at {@value #SPEED}x the pace of its time stamps, in slices of 0.1 s of robot time. With
     * {@code renameTo}, halfway the log is renamed there and an empty one created, and the rest still goes to the
     * renamed file (the logger's handle); with {@code pause}, another program writes a line to the new file first and
     * the logger pauses past the quiet time, so that watch has turned to the new file when the rest comes.
     */
    private static void write(Path log, String text, Path renameTo, boolean pause) throws Exception {
        String[] lines = text.split("(?<=\n)", -1);
        try (OutputStream out = Files.newOutputStream(log, StandardOpenOption.CREATE, StandardOpenOption.APPEND)) {
            StringBuilder slice = new StringBuilder();
            double sliceStart = 0;
            for (int i = 0; i < lines.length; i++) {
                String line = lines[i];
                double t = time(line);
                if (!Double.isNaN(t) && t - sliceStart >= 0.1) {
                    out.write(slice.toString().getBytes(StandardCharsets.UTF_8));
                    out.flush();
                    slice.setLength(0);
                    Thread.sleep(Math.round((t - sliceStart) * 1000 / SPEED));
                    sliceStart = t;
                }
                if (renameTo != null && i == lines.length / 2 && !Double.isNaN(t)) {
                    Files.move(log, renameTo);
                    Files.writeString(log, pause ? "yarprun: starting\n" : "");
                    renameTo = null;
                    if (pause) {
                        Thread.sleep(LogFollower.QUIET_MILLIS * 3 / 2);
                    }
                }
                slice.append(line);
            }
            out.write(slice.toString().getBytes(StandardCharsets.UTF_8));
        }
    }

    /** The time stamp of a record's first line, or NaN for another line. */
    private static double time(String line) {
        int tab = line.indexOf('\t');
        if (tab <= 0 || !Character.isDigit(line.charAt(0))) {
            return Double.NaN;
        }
        try {
            return Double.parseDouble(line.substring(0, tab));
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /** Simulated runs, each watched alone from a file of its own to know what it gives. */
    private List<PoolRun> pool(ModelSet models) throws IOException {
        List<PoolRun> pool = new ArrayList<>();
        long seed = 7001;
        for (Scenario s : List.of(Scenario.DEPLETED, Scenario.RECHARGE, Scenario.DEPLETED, Scenario.DIRECT,
                Scenario.DEPLETED, Scenario.RECHARGE)) {
            String text = LogWriter.toText(Simulator.run(s, seed++, SimOptions.defaults()), SimOptions.defaults());
            Path alone = Files.writeString(dir.resolve("alone-" + seed + ".log"), text);
            int[] events = new int[2];
            PredictiveMonitor m = new PredictiveMonitor(models, ABSTRACTION, 0, ABSTRACTION.confirm(), e -> {
                if (e instanceof MonitorEvent.Warning) {
                    events[0]++;
                } else if (e instanceof MonitorEvent.Violation) {
                    events[1]++;
                }
            });
            try (LogWatcher w = new LogWatcher(alone, m, p -> { })) {
                w.drain();
            }
            pool.add(new PoolRun(text, m.records(), events[0], events[1]));
        }
        return pool;
    }

    private static void count(Map<String, AtomicLong> counts, WatchedLog log) {
        counts.computeIfAbsent(log.path().getFileName().toString(), k -> new AtomicLong()).incrementAndGet();
    }

    private static long got(Map<String, AtomicLong> counts, String name) {
        AtomicLong n = counts.get(name);
        return n == null ? 0 : n.get();
    }

    private static long descriptors() {
        return FleetDescriptorsTest.descriptors();
    }

    private static void await(BooleanSupplier condition, String what, int seconds) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("not within " + seconds + " s: " + what);
            }
            Thread.sleep(20);
        }
    }
}
