package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import dev.predmon.parse.LogRecord;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.stream.LongStream;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * A fleet of more logs than it may hold files open keeps following every one of them, by closing the files of idle
 * logs and reopening them when they change; logs that are deleted give their descriptors back. The descriptors are
 * counted in {@code /proc/self/fd}.
 */
class FleetDescriptorsTest {

    private static final Abstraction ABSTRACTION = AbstractionFiles.defaults();
    private static final int LOGS = 60;
    private static final int BUDGET = 8;
    private static final Path FDS = Path.of("/proc/self/fd");

    @TempDir
    Path dir;

    private final Map<String, Queue<Long>> seen = new ConcurrentHashMap<>();
    private final AtomicInteger told = new AtomicInteger();

    @Test
    @Timeout(120)
    void moreLogsThanOpenFilesAreAllFollowedAndDeletedOnesGiveTheirDescriptorsBack() throws Exception {
        assumeTrue(Files.isDirectory(FDS), "no /proc/self/fd here");
        Path robots = Files.createDirectories(dir.resolve("robots"));
        Fleet fleet = new Fleet(LearnedModels.modelSet(List.of(), ABSTRACTION), ABSTRACTION, 0, 0,
                new FleetListener() {
                    @Override
                    public void event(WatchedLog log, MonitorEvent event) {
                    }

                    @Override
                    public void record(WatchedLog log, LogRecord record) {
                        seen.computeIfAbsent(log.path().getFileName().toString(),
                                n -> new ConcurrentLinkedQueue<>()).add(Long.parseLong(record.arguments()));
                    }

                    @Override
                    public void notice(String line) {
                        if (line.contains("logs need more open files than this process may hold (8)")) {
                            told.incrementAndGet();
                        }
                    }
                });
        fleet.limits(Duration.ofMillis(300), BUDGET);
        LogSources sources = new LogSources(List.of(robots));
        AtomicReference<Throwable> failed = new AtomicReference<>();
        Thread following = new Thread(() -> {
            try {
                fleet.follow(sources, TimeUnit.MILLISECONDS.toNanos(5), false, TimeUnit.MILLISECONDS.toNanos(100));
            } catch (Throwable t) {
                failed.set(t);
            }
        }, "fleet-follow");
        try (fleet) {
            following.start();
            Thread.sleep(500);
            long start = descriptors();
            for (int i = 0; i < LOGS; i++) {
                FleetFollowTest.append(robots.resolve("robot-" + i + ".log"), 0, 3);
            }
            await(() -> everyLogSaw(3), "the first records of every log");
            assertTrue(descriptors() <= start + BUDGET, "at most the budget open: " + (descriptors() - start));
            for (int i = LOGS - 1; i >= 0; i--) { // the logs idle longest first: each is reopened
                FleetFollowTest.append(robots.resolve("robot-" + i + ".log"), 3, 5);
            }
            await(() -> everyLogSaw(5), "an append to every log, each closed meanwhile");
            assertTrue(descriptors() <= start + BUDGET, "at most the budget open: " + (descriptors() - start));
            assertEquals(1, told.get(), "said once");
            try (Stream<Path> logs = Files.list(robots)) {
                for (Path p : logs.toList()) {
                    Files.delete(p);
                }
            }
            await(() -> descriptors() <= start, "deleted logs give their descriptors back: " + (descriptors() - start)
                    + " more than at the start");
            assertEquals(null, failed.get());
            following.interrupt();
            following.join(10_000);
        }
        assertEquals(null, failed.get());
    }

    private boolean everyLogSaw(int records) {
        List<Long> expected = LongStream.range(0, records).boxed().toList();
        for (int i = 0; i < LOGS; i++) {
            Queue<Long> got = seen.get("robot-" + i + ".log");
            if (got == null || !List.copyOf(got).equals(expected)) {
                return false;
            }
        }
        return true;
    }

    static long descriptors() {
        try (Stream<Path> fds = Files.list(FDS)) {
            return fds.count() - 1; // the listing's own
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("not within 30 s: " + what);
            }
            Thread.sleep(10);
        }
    }

    /**
     * Over the budget, the log whose last new record is oldest is closed first: a log read again since it was opened
     * is kept, one opened before it and idle since is closed.
     */
    @Test
    void theLogIdleLongestIsClosedFirst() throws Exception {
        Path robots = Files.createDirectories(dir.resolve("robots"));
        List<Path> paths = new ArrayList<>();
        for (int i = 0; i <= BUDGET; i++) {
            paths.add(robots.resolve("robot-" + i + ".log"));
            FleetFollowTest.append(paths.get(i), 0, 1);
        }
        try (Fleet fleet = new Fleet(LearnedModels.modelSet(List.of(), ABSTRACTION), ABSTRACTION, 0, 0, (l, e) -> { })) {
            fleet.limits(Duration.ofMinutes(1), BUDGET);
            paths.forEach(fleet::add);
            List<WatchedLog> logs = fleet.logs();
            fleet.poll(); // nine opened in turn: robot-0, read first, is closed
            assertEquals(List.of(0, 1, 1), openFiles(logs.subList(0, 3)));
            FleetFollowTest.append(paths.get(1), 1, 2);
            fleet.poll(); // robot-1 has something new
            FleetFollowTest.append(paths.get(0), 1, 2);
            fleet.poll(); // robot-0 is opened again: one must go
            assertEquals(List.of(1, 1, 0), openFiles(logs.subList(0, 3)),
                    "robot-2, idle since it was opened, goes; robot-1, opened before it but read since, stays");
            assertEquals(BUDGET, fleet.openFiles());
        }
    }

    private static List<Integer> openFiles(List<WatchedLog> logs) {
        return logs.stream().map(l -> l.watcher().openFiles()).toList();
    }

    @Test
    void theBudgetLeavesAThousandAndTwentyFourDescriptorsOrHalfOfFewFree() {
        // a limit of 20,000 with 50 in use: 10,000 busy logs are all held open (half would be 9,975, and a log
        // closed as idle would be reopened at its next write, again and again)
        assertEquals(18_926, OpenFiles.budget(19_950));
        assertEquals(1_976, OpenFiles.budget(3_000));
        assertEquals(1_024, OpenFiles.budget(2_048));
        assertEquals(500, OpenFiles.budget(1_000)); // ulimit -n 1024: half, as before
        assertEquals(8, OpenFiles.budget(10)); // the floor
    }
}
