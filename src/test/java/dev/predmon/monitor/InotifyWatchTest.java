package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * predmon's own inotify reader tells what the JDK's watch service tells (creations, renames, deletions, writes, a
 * directory gone), loses no write when thousands of events wait between two drains, turns a kernel queue overflow
 * into an overflow of every directory, and gives way to the JDK's watch service where it cannot be had.
 */
class InotifyWatchTest {

    private static final Abstraction ABSTRACTION = AbstractionFiles.defaults();

    @TempDir
    Path dir;

    private DirectoryWatch watch;

    @AfterEach
    void close() throws IOException {
        if (watch != null) {
            watch.close();
        }
    }

    /** The watch of a kind: predmon's own inotify reader ("own") or the JDK's ("jdk"); skipped where there is none. */
    private DirectoryWatch open(String kind) {
        watch = kind.equals("own") ? InotifyWatch.open(InotifyWatch.LIBRARY) : JdkWatch.open(why -> { });
        assumeTrue(watch != null, "no " + kind + " file-change notification here");
        return watch;
    }

    private InotifyWatch own() {
        return (InotifyWatch) open("own");
    }

    @ParameterizedTest
    @ValueSource(strings = {"own", "jdk"})
    void creationsRenamesAndDeletionsAreToldInOrderAndWritesOnce(String kind) throws Exception {
        DirectoryWatch w = open(kind);
        DirectoryWatch.Key key = w.register(dir);
        Path log = dir.resolve("robot.log");
        Files.createFile(log);
        Files.writeString(log, "a\n", StandardOpenOption.APPEND);
        Files.writeString(log, "b\n", StandardOpenOption.APPEND);
        Files.move(log, dir.resolve("robot.log.1")); // rename rotation
        Files.createFile(log);
        Files.delete(dir.resolve("robot.log.1"));
        Thread.sleep(200); // all read and queued: writes queued before one take are one change
        List<DirectoryWatch.Change> changes = drain(w, new ArrayList<>());
        List<String> structural = new ArrayList<>();
        int writes = 0;
        for (DirectoryWatch.Change c : changes) {
            assertEquals(key, c.key());
            if (c.kind() == DirectoryWatch.Kind.MODIFIED) {
                writes += c.name().toString().equals("robot.log") ? 1 : 0;
            } else {
                structural.add(c.kind() + " " + c.name());
            }
        }
        assertEquals(List.of("CREATED robot.log", "DELETED robot.log", "CREATED robot.log.1", "CREATED robot.log",
                "DELETED robot.log.1"), structural);
        assertEquals(1, writes, "two writes before one take, told once");
    }

    @ParameterizedTest
    @ValueSource(strings = {"own", "jdk"})
    void aDeletedDirectoryIsNoLongerWatchedAndALinkToADirectoryIsTheSameKey(String kind) throws Exception {
        DirectoryWatch w = open(kind);
        Path sub = Files.createDirectory(dir.resolve("robots"));
        DirectoryWatch.Key key = w.register(sub);
        assertEquals(key, w.register(Files.createSymbolicLink(dir.resolve("link"), sub)), "one directory, one key");
        Files.delete(sub);
        List<DirectoryWatch.Key> invalid = new ArrayList<>();
        drain(w, invalid);
        assertEquals(List.of(key), invalid);
        assertFalse(key.isValid());
    }

    /**
     * A directory that cannot be watched is polled, with why on stderr: said as the JDK's watch service says it, a
     * watch limit reached included (which a test cannot reach: the limit is the machine's).
     */
    @ParameterizedTest
    @ValueSource(strings = {"own", "jdk"})
    void whatCannotBeWatchedSaysWhy(String kind) throws Exception {
        DirectoryWatch w = open(kind);
        IOException missing = assertThrows(IOException.class, () -> w.register(dir.resolve("later")));
        assertEquals("NoSuchFileException", DirectoryWatch.why(missing));
        Path file = Files.createFile(dir.resolve("robot.log"));
        IOException notDirectory = assertThrows(IOException.class, () -> w.register(file));
        assertEquals("NotDirectoryException", DirectoryWatch.why(notDirectory));
        assertEquals("User limit of inotify watches reached", DirectoryWatch.why(Inotify.registerFailed(dir, 28)));
        w.close();
        assertEquals("the notification is closed",
                DirectoryWatch.why(assertThrows(IOException.class, () -> w.register(dir))));
    }

    /** The watch would follow a directory moved away from its logs' paths: it ends at once instead. */
    @Test
    void aDirectoryMovedAwayIsNoLongerWatched() throws Exception {
        DirectoryWatch w = own();
        Path sub = Files.createDirectory(dir.resolve("robots"));
        DirectoryWatch.Key key = w.register(sub);
        Files.move(sub, dir.resolve("robots.old"));
        List<DirectoryWatch.Key> invalid = new ArrayList<>();
        drain(w, invalid);
        assertEquals(List.of(key), invalid);
        assertFalse(key.isValid());
        Files.createDirectory(sub);
        assertTrue(w.register(sub).isValid(), "the new directory at the path is watched");
    }

    /**
     * 3,000 logs of names of 5 to 44 bytes, each written twice while the reader reads nothing (about 190 KB of
     * events, three reads of 64 KiB, events cut at every read's end): each log is told as written exactly once.
     */
    @Test
    void thousandsOfWritesBetweenTwoDrainsAreEachToldOnce() throws Exception {
        InotifyWatch w = own();
        int n = 3000;
        assumeTrue(maxQueuedEvents() > 2 * n + 100, "the kernel's inotify queue is too short here");
        List<Path> logs = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            logs.add(Files.createFile(dir.resolve(i + "-" + "x".repeat(i % 40) + ".log")));
        }
        w.register(dir);
        w.hold(true);
        for (int round = 0; round < 2; round++) {
            for (Path log : logs) {
                Files.writeString(log, "r\n", StandardOpenOption.APPEND);
            }
        }
        w.hold(false);
        Thread.sleep(200); // one drain reads them all
        Map<String, Integer> told = new HashMap<>();
        for (DirectoryWatch.Change c : drain(w, new ArrayList<>())) {
            assertEquals(DirectoryWatch.Kind.MODIFIED, c.kind(), c.toString());
            told.merge(c.name().toString(), 1, Integer::sum);
        }
        assertEquals(n, told.size(), "every log told");
        for (Path log : logs) {
            assertEquals(1, told.get(log.getFileName().toString()), log.getFileName().toString());
        }
    }

    /**
     * The kernel's queue overflows while the reader reads nothing: the writes to the logs after it are lost, and
     * every log of the fleet's directory is looked at all the same.
     */
    @Test
    void aKernelQueueOverflowHasEveryLogLookedAt() throws Exception {
        InotifyWatch w = own();
        int queue = maxQueuedEvents();
        assumeTrue(queue > 0 && queue <= 1 << 20, "the kernel's inotify queue is not known or too long to fill");
        Path other = Files.createDirectory(dir.resolve("other"));
        List<Path> logs = new ArrayList<>();
        for (int i = 0; i < 50; i++) {
            logs.add(Files.createFile(dir.resolve("robot-" + i + ".log")));
        }
        Path quiet = Files.createFile(other.resolve("quiet.log"));
        try (Fleet fleet = new Fleet(LearnedModels.modelSet(List.of(), ABSTRACTION), ABSTRACTION, 0, 0,
                (log, e) -> { });
             Wakeups wakeups = new Wakeups(w, TimeUnit.MILLISECONDS.toNanos(5), (d, why) -> { })) {
            for (Path log : logs) {
                wakeups.add(fleet.add(log));
            }
            wakeups.add(fleet.add(quiet));
            assertEquals(51, wakeups.due(0).size(), "each log looked at once when it is added");
            w.hold(true);
            // Two files written in turn: the kernel merges an event only with an identical one just before it.
            try (FileChannel a = FileChannel.open(Files.createFile(dir.resolve("a.tmp")), StandardOpenOption.WRITE);
                 FileChannel b = FileChannel.open(Files.createFile(dir.resolve("b.tmp")), StandardOpenOption.WRITE)) {
                for (int i = 0; i < queue / 2 + 10; i++) {
                    a.write(ByteBuffer.wrap(new byte[] {'x'}));
                    b.write(ByteBuffer.wrap(new byte[] {'x'}));
                }
            }
            for (Path log : logs) {
                Files.writeString(log, "r\n", StandardOpenOption.APPEND); // lost in the full queue
            }
            w.hold(false);
            List<Path> lookedAt = new ArrayList<>();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (lookedAt.size() < 51 && System.nanoTime() < deadline) {
                for (WatchedLog log : wakeups.due(TimeUnit.MILLISECONDS.toNanos(50))) {
                    assertFalse(wakeups.onlyWritten(log), log.path() + " looked at as after lost changes");
                    lookedAt.add(log.path());
                }
            }
            assertEquals(51, lookedAt.size(), "every log of every directory looked at: " + lookedAt);
        }
    }

    /** Where the native reader cannot be had (here: a C library that does not exist), the JDK's is taken. */
    @Test
    void theJdksWatchServiceIsTakenWhereTheOwnReaderCannotBeHad() throws Exception {
        assertNull(InotifyWatch.open("predmon-no-such-library"));
        watch = DirectoryWatch.open(why -> { }, "predmon-no-such-library");
        assumeTrue(watch != null, "no file-change notification here");
        assertInstanceOf(JdkWatch.class, watch);
        DirectoryWatch.Key key = watch.register(dir);
        Files.writeString(dir.resolve("robot.log"), "r\n");
        List<DirectoryWatch.Change> changes = drain(watch, new ArrayList<>());
        assertFalse(changes.isEmpty(), "the JDK's watch service tells the new log");
        assertSame(key.getClass(), changes.get(0).key().getClass());
        assertEquals(new DirectoryWatch.Change(key, DirectoryWatch.Kind.CREATED, Path.of("robot.log")),
                changes.get(0));
    }

    @Test
    void theJdksWatchServiceIsTakenWhenAskedFor() throws Exception {
        String was = System.setProperty(DirectoryWatch.NOTIFY_PROPERTY, "jdk");
        try {
            watch = DirectoryWatch.open();
            assumeTrue(watch != null, "no file-change notification here");
            assertInstanceOf(JdkWatch.class, watch);
        } finally {
            if (was == null) {
                System.clearProperty(DirectoryWatch.NOTIFY_PROPERTY);
            } else {
                System.setProperty(DirectoryWatch.NOTIFY_PROPERTY, was);
            }
        }
    }

    /** Takes changes until none came for 300 ms; the invalid keys go to {@code invalid}. */
    private static List<DirectoryWatch.Change> drain(DirectoryWatch w, List<DirectoryWatch.Key> invalid)
            throws InterruptedException {
        List<DirectoryWatch.Change> all = new ArrayList<>();
        while (true) {
            int before = invalid.size();
            List<DirectoryWatch.Change> some = w.take(TimeUnit.MILLISECONDS.toNanos(300), invalid);
            if (some.isEmpty() && invalid.size() == before) {
                return all;
            }
            all.addAll(some);
        }
    }

    private static int maxQueuedEvents() {
        try {
            // Files.readString reads a sysctl's first byte alone (its size is 0); lines read it whole
            return Integer.parseInt(Files.readAllLines(Path.of("/proc/sys/fs/inotify/max_queued_events")).get(0).trim());
        } catch (IOException | RuntimeException e) {
            return -1;
        }
    }
}
