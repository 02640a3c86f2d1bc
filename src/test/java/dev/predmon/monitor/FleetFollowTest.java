package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import dev.predmon.parse.LogRecord;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.stream.LongStream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * How a following fleet learns that a log changed. With the operating system's notification, the pause and the
 * backstop are set to an hour, so that nothing but a notification can wake the fleet within the tests' bounds; with
 * forced polling, the backstop is an hour and the pause short. Either way the fleet must see an append, a new log in
 * its directory, rotation by rename (with the old file still written), copytruncate, and deletion, each record once.
 */
class FleetFollowTest {

    private static final Abstraction ABSTRACTION = AbstractionFiles.defaults();
    private static final long HOUR = TimeUnit.HOURS.toNanos(1);
    private static final long PAUSE = TimeUnit.MILLISECONDS.toNanos(5);

    @TempDir
    Path dir;

    /** The sequence numbers of the records each log (by file name) gave, in order. */
    private final Map<String, Queue<Long>> seen = new ConcurrentHashMap<>();
    private final AtomicLong seenCount = new AtomicLong();

    private Fleet fleet() {
        return new Fleet(LearnedModels.modelSet(List.of(), ABSTRACTION), ABSTRACTION, 0, 0, new FleetListener() {
            @Override
            public void event(WatchedLog log, MonitorEvent event) {
            }

            @Override
            public void record(WatchedLog log, LogRecord record) {
                seen.computeIfAbsent(log.path().getFileName().toString(), n -> new ConcurrentLinkedQueue<>())
                        .add(Long.parseLong(record.arguments()));
                seenCount.incrementAndGet();
            }
        });
    }

    @Test
    @Timeout(60)
    void notificationAloneShowsAppendsNewLogsAndRotations() throws Exception {
        assumeTrue(notifying(), "no file-change notification here");
        rotations(false, HOUR);
    }

    @Test
    @Timeout(60)
    void forcedPollingShowsTheSame() throws Exception {
        rotations(true, PAUSE);
    }

    private void rotations(boolean polling, long pause) throws Exception {
        Path logs = Files.createDirectories(dir.resolve("fleet"));
        Path a = logs.resolve("a.log");
        append(a, 0, 3);
        LogSources sources = new LogSources(List.of(logs));
        try (Fleet fleet = fleet(); Following following = new Following(fleet, sources, pause, polling)) {
            await(() -> seen("a.log").equals(range(0, 3)), "the log as it was");
            append(a, 3, 5);
            await(() -> seen("a.log").equals(range(0, 5)), "an append");
            append(logs.resolve("b.log"), 100, 102);
            await(() -> seen("b.log").equals(range(100, 102)), "a new log in the directory");
            try (OutputStream old = Files.newOutputStream(a, StandardOpenOption.APPEND)) {
                Files.move(a, logs.resolve("a.log.1"));
                old.write(WatchSoakTest.record(5, "\n").getBytes(StandardCharsets.UTF_8));
                old.flush();
                await(() -> seen("a.log").equals(range(0, 6)), "a write to the file renamed away, still held");
            }
            append(a, 6, 7);
            await(() -> seen("a.log").equals(range(0, 7)), "the new file at the path");
            Files.write(a, WatchSoakTest.record(7, "\n").getBytes(StandardCharsets.UTF_8)); // truncated, rewritten
            await(() -> seen("a.log").equals(range(0, 8)), "copytruncate");
            Files.delete(a);
            append(a, 8, 9);
            await(() -> seen("a.log").equals(range(0, 9)), "deleted and created again");
            following.check();
        }
        assertEquals(List.of("a.log", "b.log"), seen.keySet().stream().sorted().toList());
    }

    /**
     * The rotation soak of {@link WatchSoakTest}, through a fleet woken by nothing but the notification (and the
     * looks at a log whose renamed file must first be quiet: 30 rotations, as each rename waits that second out).
     */
    @Test
    @Timeout(120)
    void thirtyRotationsSeenThroughNotificationLoseAndRepeatNoRecord() throws Exception {
        assumeTrue(notifying(), "no file-change notification here");
        Path log = dir.resolve("robot.log");
        AtomicLong written = new AtomicLong();
        AtomicReference<Throwable> writerFailure = new AtomicReference<>();
        Thread writer = new Thread(() -> {
            try {
                WatchSoakTest.write(log, written, seenCount, 30);
            } catch (Throwable t) {
                writerFailure.set(t);
            }
        }, "fleet-soak-writer");
        try (Fleet fleet = fleet()) {
            fleet.add(log);
            try (Following following = new Following(fleet, new LogSources(List.of(log)), HOUR, false)) {
                writer.start();
                writer.join();
                await(() -> seenCount.get() >= written.get(), "every record written");
                following.check();
            }
        }
        assertEquals(null, writerFailure.get());
        assertEquals(range(0, written.get()), seen("robot.log"), "each record once, in order");
    }

    /**
     * A log whose directory does not exist yet cannot be watched: it is polled until the directory appears, then
     * watched (the pause is an hour, so once read, the append after it can only have come by notification).
     */
    @Test
    @Timeout(60)
    void aLogWhoseDirectoryAppearsLaterIsWatchedOnceItIsThere() throws Exception {
        assumeTrue(notifying(), "no file-change notification here");
        Path log = dir.resolve("later/run.log");
        try (Fleet fleet = fleet()) {
            fleet.add(log);
            try (Following following = new Following(fleet, new LogSources(List.of(log)), HOUR, false)) {
                Thread.sleep(100);
                Files.createDirectories(log.getParent());
                append(log, 0, 2);
                await(() -> seen("run.log").equals(range(0, 2)), "the file in the new directory, by the retry");
                append(log, 2, 4);
                await(() -> seen("run.log").equals(range(0, 4)), "an append, notified");
                following.check();
            }
        }
    }

    @Test
    void networkAndFuseFileSystemsArePolled() {
        for (String local : List.of("ext4", "xfs", "btrfs", "tmpfs", "overlay", "zfs", "fuseblk", "apfs", "NTFS")) {
            assertTrue(DirectoryWatch.notifies(local), local);
        }
        for (String remote : List.of("nfs", "nfs4", "cifs", "smb3", "9p", "fuse.sshfs", "fuse", "ceph", "virtiofs")) {
            assertFalse(DirectoryWatch.notifies(remote), remote);
        }
    }

    private static boolean notifying() throws IOException {
        DirectoryWatch watch = DirectoryWatch.open();
        if (watch == null) {
            return false;
        }
        watch.close();
        return true;
    }

    private List<Long> seen(String name) {
        return List.copyOf(seen.getOrDefault(name, new ConcurrentLinkedQueue<>()));
    }

    private static List<Long> range(long from, long to) {
        return LongStream.range(from, to).boxed().toList();
    }

    /** Appends records {@code from} to {@code to} (exclusive), in one write, creating the file if need be. */
    static void append(Path log, long from, long to) throws IOException {
        StringBuilder text = new StringBuilder();
        for (long seq = from; seq < to; seq++) {
            text.append(WatchSoakTest.record(seq, "\n"));
        }
        Files.write(log, text.toString().getBytes(StandardCharsets.UTF_8), StandardOpenOption.CREATE,
                StandardOpenOption.APPEND);
    }

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("not seen within 20 s: " + what);
            }
            Thread.sleep(5);
        }
    }

    /** {@link Fleet#follow} on a thread of its own, with the backstop an hour away, as {@code watch} runs it. */
    private static final class Following implements AutoCloseable {

        private final Thread thread;
        private final AtomicReference<Throwable> failed = new AtomicReference<>();

        Following(Fleet fleet, LogSources sources, long pauseNanos, boolean polling) throws IOException {
            sources.find().forEach(fleet::add);
            thread = new Thread(() -> {
                try {
                    fleet.follow(sources, pauseNanos, polling, HOUR);
                } catch (Throwable t) {
                    failed.set(t);
                }
            }, "fleet-follow");
            thread.start();
        }

        /** Fails if the loop failed or stopped. */
        void check() {
            assertEquals(null, failed.get());
            assertTrue(thread.isAlive(), "still following");
        }

        @Override
        public void close() throws Exception {
            thread.interrupt();
            thread.join(TimeUnit.SECONDS.toMillis(10));
            assertFalse(thread.isAlive(), "stops when interrupted");
            if (failed.get() != null) {
                throw new AssertionError(String.format(Locale.ROOT, "following failed: %s", failed.get()),
                        failed.get());
            }
        }
    }
}
