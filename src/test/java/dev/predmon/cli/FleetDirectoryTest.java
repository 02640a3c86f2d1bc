package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.stream.Collectors;
import java.util.stream.IntStream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A directory given to {@code watch}: the files in it that are not logs (notes, a binary) are skipped silently when a
 * log there is judged, and each is said once, with no summary of nothing, when none is.
 */
class FleetDirectoryTest {

    @TempDir
    Path tmp;
    Path models;
    Path robots;

    @BeforeEach
    void setUp() throws Exception {
        models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(tmp.resolve("logs"), models, "recharge");
        robots = Files.createDirectories(tmp.resolve("robots"));
        Files.writeString(robots.resolve("notes.txt"), "robot 1 starts at 9, robot 2 at 10\n");
        byte[] junk = new byte[3000];
        new Random(17).nextBytes(junk);
        Files.write(robots.resolve("core.log"), junk);
        // longer than the 200 lines after which watch says, while following, that a file holds no record
        Files.writeString(robots.resolve("build.txt"), IntStream.range(0, 300).mapToObj(i -> "step " + i)
                .collect(Collectors.joining("\n", "", "\n")));
    }

    @Test
    @Timeout(30)
    void besideAGoodLogTheOtherFilesAreSkippedSilently() throws Exception {
        Path good = Files.writeString(robots.resolve("robot-1.log"), HandRuns.recharge().text());
        Cli once = Cli.run("watch", "--no-follow", "--log", robots.toString(), "--models", models.toString());
        assertEquals(ExitCodes.OK, once.code(), once.err());
        assertEquals("", once.err());
        assertEquals(List.of("end of " + good + ": "), once.out().lines().filter(l -> l.startsWith("end of "))
                .map(l -> l.substring(0, l.indexOf(": ") + 2)).toList(), once.out());
        assertTrue(once.out().lines().allMatch(l -> l.startsWith("end of " + good) || l.startsWith(good + ": ")),
                "only the log's lines: " + once.out());

        Cli.Running w = Cli.start("watch", "--log", robots.toString(), "--models", models.toString(), "--poll-ms", "5");
        Thread.sleep(500); // polls enough to have read every file, and to have said what it would say
        w.stop();
        assertEquals(ExitCodes.OK, w.code().get(), w.err().toString());
        assertEquals("", w.err().toString());
        assertFalse(w.out().toString().contains("notes.txt") || w.out().toString().contains("core.log")
                || w.out().toString().contains("build.txt"), w.out().toString());
    }

    @Test
    @Timeout(30)
    void withNoLogThereEachFileIsSaidOnce() throws Exception {
        Cli once = Cli.run("watch", "--no-follow", "--log", robots.toString(), "--models", models.toString());
        assertEquals(ExitCodes.BAD_INPUT, once.code());
        assertEquals(3, once.err().lines().count(), once.err());

        Cli.Running w = Cli.start("watch", "--log", robots.toString(), "--models", models.toString(), "--poll-ms", "5");
        Thread.sleep(500); // polls enough to have read every file, and to have said what it would say
        w.stop();
        assertEquals(ExitCodes.BAD_INPUT, w.code().get(), w.err().toString());
        List<String> lines = w.err().toString().lines().toList();
        for (String file : List.of("notes.txt", "core.log", "build.txt")) {
            assertEquals(1, lines.stream().filter(l -> l.contains(file)).count(), file + " once: " + w.err());
        }
        assertTrue(lines.stream().allMatch(l -> l.contains("no YARP monitor record in ")), w.err().toString());
        assertEquals("", w.out().toString(), "no summary of nothing");
    }
}
