package dev.predmon.monitor;

import dev.predmon.event.LogEvent;
import dev.predmon.hooks.CommandHooks;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
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
import java.util.function.Supplier;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * Chaos soak: {@value #LOGS} robots' logs in one watched directory, each appended at {@value #SPEED}x robot pace with
 * runs whose verdicts are known (each run watched alone, {@link ChaosRuns}), and between runs renamed (also twice
 * before the logger reopens, the middle file left empty), renamed while the logger goes on writing the renamed file
 * (also after a pause past the turn to the new file, which another program wrote a line to), copytruncated,
 * truncated, deleted, replaced by a FIFO or by a directory ({@link ChaosWriter}). Two robots' battery sensors flap at
 * the floor (19.9, 20.1, ...: a warning, a violation and a recovery at every crossing), and robots freeze for 40 s in
 * the middle of a navigation due within 45 s. Every event runs a hook command that takes a second, as
 * {@code --on-warning} does. Every warning and violation that watching each run alone gives must arrive, every
 * robot's first warning must reach its hook, and once the logs are gone the process holds the descriptors it held
 * before.
 */
class ChaosSoakTest {

    private static final int LOGS = 12;
    private static final int SPEED = 8;
    /** The robots whose battery sensor flaps; the robot whose first run freezes. */
    private static final int FLAPPING = 2;
    private static final int FREEZING = FLAPPING;
    private static final long CHAOS_NANOS = TimeUnit.SECONDS.toNanos(40);
    private static final Path FDS = Path.of("/proc/self/fd");

    @TempDir
    Path dir;

    private final Map<String, AtomicLong> warnings = new ConcurrentHashMap<>();
    private final Map<String, AtomicLong> violations = new ConcurrentHashMap<>();
    private final Map<String, AtomicLong> alarms = new ConcurrentHashMap<>();
    private final Map<String, AtomicLong> records = new ConcurrentHashMap<>();
    /** Per log, the line of its first warning, as its hook prints it. */
    private final Map<String, String> firstWarnings = new ConcurrentHashMap<>();
    private final List<String> hookReports = Collections.synchronizedList(new ArrayList<>());

    @Test
    @Timeout(240)
    void everyWarningAndViolationArrivesAndEveryRobotsFirstWarningReachesItsHook() throws Exception {
        assumeTrue(Files.isDirectory(FDS), "no /proc/self/fd here");
        assumeTrue(Files.isExecutable(Path.of("/bin/sh")), "hook commands run with /bin/sh, which this system lacks");
        ChaosRuns runs = new ChaosRuns(dir);
        List<ChaosRuns.Run> pool = runs.pool;
        assertTrue(pool.stream().anyMatch(r -> r.warnings() > 0) && pool.stream().anyMatch(r -> r.warnings() == 0),
                "the pool holds runs that warn and runs that do not");
        Path robots = Files.createDirectories(dir.resolve("robots"));
        Path calls = dir.resolve("calls");
        String hook = "echo \"$PREDMON_EVENT $PREDMON_LOG $PREDMON_LINE\" >> '" + calls + "'; sleep 1";
        CommandHooks hooks = new CommandHooks(hook, hook, hook, Duration.ofSeconds(5), CommandHooks.HOLD, 20.0,
                hookReports::add);
        Fleet fleet = new Fleet(runs.models, runs.abstraction, 0, runs.abstraction.confirm(), new FleetListener() {
            @Override
            public void event(WatchedLog log, MonitorEvent e) {
                String name = log.path().getFileName().toString();
                if (e instanceof MonitorEvent.Warning w) {
                    count(warnings, log);
                    firstWarnings.putIfAbsent(name, "warning " + name + " " + w.line());
                } else if (e instanceof MonitorEvent.Violation) {
                    count(violations, log);
                }
                if (e instanceof MonitorEvent.Warning || e instanceof MonitorEvent.Violation
                        || e instanceof MonitorEvent.Recovered) {
                    count(alarms, log);
                    hooks.event(LogEvent.of(name, e));
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
        Map<String, AtomicLong> done = new ConcurrentHashMap<>();
        long began = System.nanoTime();
        try (fleet; hooks) {
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
                        robot(robots.resolve(name), index, runs, sum, done);
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
            // the hooks take their turns, a second each, while the flapping robots' alarms come and go
            await(() -> hookCalls(calls).containsAll(firstWarnings.values()), () -> "every robot's first warning "
                    + "runs its hook: " + firstWarnings.values().stream().filter(w -> !hookCalls(calls).contains(w))
                    .toList() + " not yet; " + hookReports.stream().filter(r -> r.contains("not run")).limit(3)
                    .toList(), 90);
            hooks.close(); // its commands hold descriptors of pipes until they end
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
        long logs = expected.size();
        int wantWarnings = expected.values().stream().mapToInt(s -> s[0]).sum();
        int wantViolations = expected.values().stream().mapToInt(s -> s[1]).sum();
        long gotWarnings = expected.keySet().stream().mapToLong(n -> got(warnings, n)).sum();
        long gotViolations = expected.keySet().stream().mapToLong(n -> got(violations, n)).sum();
        long flapCalls = hookCalls(calls).stream().filter(c -> c.contains(" robot-0.log ")).count();
        System.out.printf(Locale.ROOT, "chaos soak: %d logs, %s, warnings %d of %d, violations %d of %d, first "
                        + "warnings at their hook %d of %d, the flapping robot-0's %d alarm events ran %d hook "
                        + "commands, %.1f s%n", logs, done, gotWarnings, wantWarnings, gotViolations, wantViolations,
                firstWarnings.size(), firstWarnings.size(), got(alarms, "robot-0.log"), flapCalls,
                (System.nanoTime() - began) / 1e9);
        for (Map.Entry<String, int[]> e : expected.entrySet()) {
            assertEquals(e.getValue()[0], got(warnings, e.getKey()), e.getKey() + ": warnings");
            assertEquals(e.getValue()[1], got(violations, e.getKey()), e.getKey() + ": violations");
            assertTrue(e.getValue()[0] == 0 || firstWarnings.containsKey(e.getKey()), e.getKey());
        }
        assertTrue(firstWarnings.size() > FLAPPING, "the flapping robots and others warned: " + firstWarnings.keySet());
        assertTrue(flapCalls * 5 < got(alarms, "robot-0.log"), "the hold time keeps a flapping reading from running "
                + "a command at every crossing: " + flapCalls + " commands for " + got(alarms, "robot-0.log"));
        for (ChaosWriter.Chaos c : ChaosWriter.Chaos.values()) {
            assertTrue(done.containsKey(c.name()), "every kind of chaos happened: " + done);
        }
        assertTrue(done.containsKey("flapping") && done.containsKey("freeze"), done.toString());
    }

    /**
     * One robot: runs one after another, with chaos before each but the first. The flapping robots write the flapping
     * run every time; robot {@value #FREEZING} freezes in its first run; the others take runs from the pool, which
     * holds the freeze too.
     */
    private void robot(Path log, int index, ChaosRuns runs, int[] sum, Map<String, AtomicLong> done) throws Exception {
        Random random = new Random(index);
        ChaosWriter.Chaos[] kinds = ChaosWriter.Chaos.values();
        long end = System.nanoTime() + CHAOS_NANOS;
        String name = log.getFileName().toString();
        for (int n = 0; System.nanoTime() < end || n < 2; n++) {
            ChaosRuns.Run run = index < FLAPPING ? runs.flapping : index == FREEZING && n == 0 ? runs.freeze
                    : runs.pool.get(random.nextInt(runs.pool.size()));
            ChaosWriter.Chaos chaos = n == 0 ? null : kinds[(index + n) % kinds.length];
            if (chaos != null) {
                ChaosWriter.apply(chaos, log, name, n);
                // (the paused writer is a way of writing, counted below; applied before a run it is a rename)
                add(done, chaos == ChaosWriter.Chaos.RENAME_PAUSED_WRITTEN ? ChaosWriter.Chaos.RENAME.name()
                        : chaos.name());
            }
            add(done, run.kind());
            long before = got(records, name);
            if (chaos == null || n % 3 != 0 || !Files.exists(log)) {
                ChaosWriter.write(log, run.text(), SPEED, null, false);
            } else { // logrotate's create while the logger writes: it goes on in the renamed file
                boolean paused = (index + n) % 2 == 0; // and pauses first, past the turn to the new file
                ChaosWriter.write(log, run.text(), SPEED, log.resolveSibling(name + ".w" + n), paused);
                add(done, paused ? ChaosWriter.Chaos.RENAME_PAUSED_WRITTEN.name()
                        : ChaosWriter.Chaos.RENAME_WHILE_WRITTEN.name());
            }
            sum[0] += run.warnings();
            sum[1] += run.violations();
            // copytruncate and truncate lose what was not read before: what no follower of a path can see
            await(() -> got(records, name) >= before + run.records(), name + ": the run is read", 30);
        }
    }

    private static void add(Map<String, AtomicLong> done, String what) {
        done.computeIfAbsent(what, k -> new AtomicLong()).incrementAndGet();
    }

    /** The lines the hook commands wrote: event, log, line. */
    private static List<String> hookCalls(Path calls) {
        try {
            return Files.exists(calls) ? Files.readAllLines(calls) : List.of();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
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
        await(condition, () -> what, seconds);
    }

    private static void await(BooleanSupplier condition, Supplier<String> what, int seconds)
            throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("not within " + seconds + " s: " + what.get());
            }
            Thread.sleep(20);
        }
    }
}
