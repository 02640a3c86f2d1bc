package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * A directory whose logs must be polled because it cannot be watched is told once, with why, however many logs it
 * holds and however often it is tried again; a directory that does not exist yet is not (it is watched once it
 * does). A watch service closed before use stands for one that refuses every directory: a watch limit reached or an
 * unreadable directory cannot be arranged in a test (root reads every directory, and the limit is the machine's).
 */
class WakeupsTest {

    private static final Abstraction ABSTRACTION = AbstractionFiles.defaults();

    @TempDir
    Path dir;

    @Test
    void aDirectoryThatCannotBeWatchedIsToldOnce() throws Exception {
        DirectoryWatch watch = DirectoryWatch.open();
        assumeTrue(watch != null, "no file-change notification here");
        watch.close();
        Path a = Files.createDirectories(dir.resolve("a"));
        Path b = Files.createDirectories(dir.resolve("b"));
        List<String> told = new ArrayList<>();
        try (Fleet fleet = new Fleet(LearnedModels.modelSet(List.of(), ABSTRACTION), ABSTRACTION, 0, 0,
                (log, e) -> { });
             Wakeups wakeups = new Wakeups(watch, TimeUnit.MILLISECONDS.toNanos(5),
                     (d, why) -> told.add(d.getFileName() + ": " + why))) {
            for (Path log : List.of(a.resolve("1.log"), a.resolve("2.log"), b.resolve("1.log"),
                    dir.resolve("later/1.log"))) {
                wakeups.add(fleet.add(log));
            }
            wakeups.recheck();
            assertFalse(wakeups.notifying(), "every log polled");
        }
        assertEquals(List.of("a: the notification is closed", "b: the notification is closed"), told);
    }

    /**
     * Java's watch service holds at most 512 changes per directory until they are taken and turns the rest into an
     * overflow, after which every log of the directory is looked at as if anything had happened to it (the own inotify
     * reader, {@link InotifyWatchTest}, has the kernel's queue of 16,384 for all directories). 2,000 logs of one
     * directory, each written once while the following thread takes nothing (as when it reads what the last wakeup
     * brought), are each given as written, none as lost.
     */
    @Test
    void writesToMoreLogsOfADirectoryThanTheJdkHoldsAreEachToldAsAWrite() throws Exception {
        DirectoryWatch watch = DirectoryWatch.open();
        assumeTrue(watch != null, "no file-change notification here");
        int n = 2000;
        List<Path> files = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            files.add(Files.createFile(dir.resolve("robot-" + i + ".log")));
        }
        try (Fleet fleet = new Fleet(LearnedModels.modelSet(List.of(), ABSTRACTION), ABSTRACTION, 0, 0,
                (log, e) -> { });
             Wakeups wakeups = new Wakeups(watch, TimeUnit.MILLISECONDS.toNanos(5), (d, why) -> { })) {
            for (Path f : files) {
                wakeups.add(fleet.add(f));
            }
            assertEquals(n, wakeups.due(0).size(), "each log looked at once when it is added");
            for (int i = 0; i < n; i++) {
                Files.writeString(files.get(i), "x\n", StandardOpenOption.APPEND);
                if (i % 50 == 49) {
                    Thread.sleep(5); // 40 batches, 200 ms, the following thread taking nothing meanwhile
                }
            }
            Set<Path> written = new HashSet<>();
            Set<Path> lookedAt = new HashSet<>();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (written.size() + lookedAt.size() < n && System.nanoTime() < deadline) {
                for (WatchedLog log : wakeups.due(TimeUnit.MILLISECONDS.toNanos(50))) {
                    (wakeups.onlyWritten(log) ? written : lookedAt).add(log.path());
                }
            }
            assertEquals(Set.of(), lookedAt, "no log looked at as after lost changes");
            assertEquals(n, written.size(), "every log given as written");
        }
    }
}
