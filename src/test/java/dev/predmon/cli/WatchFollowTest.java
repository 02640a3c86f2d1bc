package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code watch} as it runs next to a robot: started before the logger has created the log, it waits, follows
 * the log as it is written in pieces, warns, and stops cleanly when interrupted (the normal way to stop it).
 */
class WatchFollowTest {

    @TempDir
    Path tmp;

    @Test
    @Timeout(30)
    void waitsForTheLogWarnsWhileItIsWrittenAndStopsCleanlyWhenInterrupted() throws Exception {
        Path logs = tmp.resolve("logs");
        Path models = tmp.resolve("models");
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", logs.toString(), "--models", models.toString()).code());

        Path log = tmp.resolve("later/run.log");
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        AtomicInteger code = new AtomicInteger(-1);
        Thread watcher = new Thread(() -> code.set(cl.execute("watch", "--log", log.toString(), "--models",
                models.toString(), "--poll-ms", "5")), "watch");
        watcher.start();

        await(() -> err.toString().contains("waiting for " + log), "announces that it waits");
        Thread.sleep(100); // a few polls on a file that is not there
        Files.createDirectories(log.getParent());
        byte[] run = HandRuns.depleted().text().getBytes(StandardCharsets.UTF_8);
        Files.write(log, new byte[0]);
        for (int from = 0; from < run.length; from += 97) { // pieces that cut lines and records anywhere
            Files.write(log, java.util.Arrays.copyOfRange(run, from, Math.min(run.length, from + 97)),
                    StandardOpenOption.APPEND);
            Thread.sleep(2);
        }
        await(() -> out.toString().contains("WARNING"), "warns");
        assertTrue(watcher.isAlive(), "follows on after the warning");

        watcher.interrupt();
        watcher.join(5_000);
        assertFalse(watcher.isAlive(), "stops when interrupted");
        assertEquals(ExitCodes.WARNING, code.get(), "interrupted after a warning: " + err);
        assertFalse(err.toString().contains("internal error"), err.toString());
    }

    @Test
    @Timeout(30)
    void interruptedBeforeTheLogAppearsIsExit0() throws Exception {
        Path logs = tmp.resolve("logs");
        Path models = tmp.resolve("models");
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", logs.toString(), "--models", models.toString()).code());
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(new StringWriter(), true));
        cl.setErr(new PrintWriter(err, true));
        AtomicInteger code = new AtomicInteger(-1);
        Thread watcher = new Thread(() -> code.set(cl.execute("watch", "--log", tmp.resolve("never.log").toString(),
                "--models", models.toString())), "watch");
        watcher.start();
        await(() -> err.toString().contains("waiting for"), "announces that it waits");
        watcher.interrupt();
        watcher.join(5_000);
        assertFalse(watcher.isAlive());
        assertEquals(ExitCodes.OK, code.get(), err.toString());
    }

    /** An interrupt can land in the middle of reading (FileChannel reads are interruptible): still a clean stop. */
    @Test
    @Timeout(60)
    void interruptedWhileReadingIsAStopNotAnError() throws Exception {
        Path logs = tmp.resolve("logs");
        Path models = tmp.resolve("models");
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", logs.toString(), "--models", models.toString()).code());
        Path log = Files.writeString(tmp.resolve("big.log"), HandRuns.recharge().text().repeat(2_000));
        for (int delayMs = 1; delayMs <= 40; delayMs += 3) {
            StringWriter err = new StringWriter();
            CommandLine cl = Main.commandLine();
            cl.setOut(new PrintWriter(new StringWriter(), true));
            cl.setErr(new PrintWriter(err, true));
            AtomicInteger code = new AtomicInteger(-1);
            Thread watcher = new Thread(() -> code.set(cl.execute("watch", "--log", log.toString(),
                    "--models", models.toString())), "watch");
            watcher.start();
            Thread.sleep(delayMs);
            watcher.interrupt();
            watcher.join(10_000);
            assertFalse(watcher.isAlive());
            assertTrue(code.get() == ExitCodes.OK || code.get() == ExitCodes.WARNING,
                    "interrupted after " + delayMs + " ms: exit " + code.get() + ": " + err);
        }
    }

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out: " + what);
            }
            Thread.sleep(5);
        }
    }
}
