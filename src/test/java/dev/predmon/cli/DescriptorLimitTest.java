package dev.predmon.cli;

import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code watch --log DIR} in a real process under {@code ulimit -n 400}, on 500 logs: more than it may hold open. It
 * says once that it closes idle logs, goes on following every one, warns on a robot that starts later, and prints
 * every log's {@code end} on SIGTERM (it exited 3, "too many open files", and watched no new robot).
 */
class DescriptorLimitTest {

    private static final int LOGS = 500;

    @TempDir
    Path tmp;

    @Test
    @Timeout(150)
    void moreLogsThanTheProcessMayOpenAreAllFollowed() throws Exception {
        Assumptions.assumeTrue(Files.isExecutable(Path.of("/bin/bash")), "ulimit needs bash");
        Path robots = Files.createDirectories(tmp.resolve("robots"));
        String run = FleetWatchTest.run(Scenario.RECHARGE, 9002);
        String head = String.join("\n", run.lines().limit(84).toList()) + "\n"; // its first 12 records
        for (int i = 0; i < LOGS; i++) {
            Files.writeString(robots.resolve("robot-" + i + ".log"), head);
        }
        List<String> command = new ArrayList<>(List.of("/bin/bash", "-c", "ulimit -n 400 && exec \"$@\"", "predmon"));
        command.addAll(Child.command("watch", "--log", robots.toString(), "--models",
                Path.of("models").toAbsolutePath().toString()));
        Path out = tmp.resolve("out.txt");
        Path err = tmp.resolve("err.txt");
        Process p = new ProcessBuilder(command).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        try {
            await(p, () -> read(err).contains("logs need more open files than this process may hold"),
                    "says that it closes idle logs", err);
            Files.writeString(robots.resolve("robot-late.log"), FleetWatchTest.run(Scenario.DEPLETED, 9001));
            await(p, () -> read(out).lines().anyMatch(l -> l.contains("robot-late.log: ") && l.contains("WARNING")),
                    "the late robot's warning", err);
            assertEquals(0, new ProcessBuilder("kill", "-TERM", Long.toString(p.pid())).start().waitFor());
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), "stops on SIGTERM");
        } finally {
            p.destroyForcibly();
        }
        assertEquals(ExitCodes.WARNING, p.exitValue(), read(err));
        assertEquals(LOGS + 1, read(out).lines().filter(l -> l.startsWith("end of ")).count(), read(err));
        assertEquals(1, read(err).lines().filter(l -> l.contains("open files")).count(), "said once: " + read(err));
        // no log is named in an error; the one log that appeared later is said to be followed
        assertEquals(0, read(err).lines().filter(l -> l.contains("robot-") && !l.endsWith("appeared; following it"))
                .count(), "no log named: " + read(err));
    }

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            return "";
        }
    }

    private static void await(Process p, BooleanSupplier condition, String what, Path err) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!condition.getAsBoolean()) {
            assertTrue(p.isAlive(), "watch ended (exit " + (p.isAlive() ? "" : p.exitValue()) + ") before: " + what
                    + "; stderr: " + read(err));
            assertTrue(System.nanoTime() < deadline, "not within 60 s: " + what + "; stderr: " + read(err));
            Thread.sleep(50);
        }
    }
}
