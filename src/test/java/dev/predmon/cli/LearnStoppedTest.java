package dev.predmon.cli;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Ctrl-C in {@code learn}, on a real child process: exit 130, as the README's table says, and one line on stderr that
 * says learn stopped and what the model directory holds (it used to be 130 and nothing).
 */
class LearnStoppedTest {

    @TempDir
    Path tmp;

    @Test
    @Timeout(120)
    void ctrlCSaysSoInOneLine() throws Exception {
        assumeSigintReachesChildren();
        // Eight copies of the sample logs: a learn of many seconds, stopped while it reads them.
        Path logs = tmp.resolve("logs");
        try (Stream<Path> files = Files.walk(Path.of("sample-logs"))) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                Path rel = Path.of("sample-logs").relativize(f);
                for (int copy = 0; copy < 8; copy++) {
                    String name = rel.getFileName().toString();
                    if (copy > 0 && !name.endsWith(".log")) {
                        continue;
                    }
                    Path to = logs.resolve(rel).resolveSibling(copy == 0 ? name : copy + "-" + name);
                    Files.createDirectories(to.getParent());
                    Files.copy(f, to);
                }
            }
        }
        Path models = tmp.resolve("models");
        Path err = tmp.resolve("err.txt");
        Process p = new ProcessBuilder(Child.command("learn", "--logs", logs.toString(), "--models", models.toString()))
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(err.toFile()).start();
        awaitReading(p, logs);
        Process kill = new ProcessBuilder("kill", "-INT", Long.toString(p.pid())).start();
        assertEquals(0, kill.waitFor(), "kill -INT");
        assertTrue(p.waitFor(30, TimeUnit.SECONDS), "stops on SIGINT");
        assertEquals(130, p.exitValue());
        List<String> lines = Files.readAllLines(err, StandardCharsets.UTF_8);
        assertEquals(List.of("predmon: learn stopped before it finished; " + models + " holds whole models, the ones "
                + "it held before (or the new ones, if they were already being put in place): run learn again"), lines);
        assertTrue(!Files.exists(models.resolve("index.json")), "stopped while reading: no models written");
    }

    /** Until the child has a log of {@code logs} open: learn is under way, its line in place. */
    private static void awaitReading(Process p, Path logs) throws Exception {
        Path fds = Path.of("/proc", Long.toString(p.pid()), "fd");
        Assumptions.assumeTrue(Files.isDirectory(fds), "no /proc to see what the child reads");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            assertTrue(p.isAlive(), "learn ended before it was stopped");
            try (Stream<Path> open = Files.list(fds)) {
                if (open.anyMatch(fd -> {
                    try {
                        return Files.readSymbolicLink(fd).startsWith(logs);
                    } catch (IOException gone) {
                        return false;
                    }
                })) {
                    return;
                }
            } catch (IOException gone) {
                // the child is changing its descriptors
            }
            Thread.sleep(5);
        }
        throw new AssertionError("learn never read a log");
    }

    /** SIGINT is ignored by processes started from a background job of a script; then it cannot be tested. */
    private static void assumeSigintReachesChildren() throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
            if (line.startsWith("SigIgn:")) {
                long ignored = Long.parseUnsignedLong(line.substring(7).strip(), 16);
                Assumptions.assumeTrue((ignored & (1L << 1)) == 0, "SIGINT is ignored in this test run");
            }
        }
    }
}
