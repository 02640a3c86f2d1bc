package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
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
}
