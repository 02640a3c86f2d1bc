package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import dev.predmon.support.Records;
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
import java.util.Arrays;
import java.util.List;
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
        Cli.Running watch = Cli.start("watch", "--log", log.toString(), "--models", models.toString(), "--poll-ms", "5");
        StringWriter out = watch.out();
        StringWriter err = watch.err();

        await(() -> err.toString().contains("waiting for " + log), "announces that it waits");
        Thread.sleep(100); // a few polls on a file that is not there
        Files.createDirectories(log.getParent());
        byte[] run = HandRuns.depleted().text().getBytes(StandardCharsets.UTF_8);
        Files.write(log, new byte[0]);
        for (int from = 0; from < run.length; from += 97) { // pieces that cut lines and records anywhere
            Files.write(log, Arrays.copyOfRange(run, from, Math.min(run.length, from + 97)),
                    StandardOpenOption.APPEND);
            Thread.sleep(2);
        }
        await(() -> out.toString().contains("WARNING"), "warns");
        assertTrue(watch.thread().isAlive(), "follows on after the warning");

        watch.stop();
        assertEquals(ExitCodes.WARNING, watch.code().get(), "interrupted after a warning: " + err);
        assertFalse(err.toString().contains("internal error"), err.toString());
        assertTrue(out.toString().contains("end of " + log + " (stopped: interrupted): "), out.toString());
        assertTrue((out.toString().contains("battery warned") || out.toString().contains("battery VIOLATED, warned")), out.toString());
    }

    /** Stopped before the log appeared: the summary, and no verdict on nothing (exit 3), not "no warning". */
    @Test
    @Timeout(30)
    void interruptedBeforeTheLogAppearsGivesNoVerdict() throws Exception {
        Path logs = tmp.resolve("logs");
        Path models = tmp.resolve("models");
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", logs.toString(), "--models", models.toString()).code());
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        AtomicInteger code = new AtomicInteger(-1);
        Path never = tmp.resolve("never.log");
        Thread watcher = new Thread(() -> code.set(cl.execute("watch", "--log", never.toString(),
                "--models", models.toString())), "watch");
        watcher.start();
        await(() -> err.toString().contains("waiting for"), "announces that it waits");
        watcher.interrupt();
        watcher.join(5_000);
        assertFalse(watcher.isAlive());
        assertEquals(ExitCodes.BAD_INPUT, code.get(), err.toString());
        assertTrue(err.toString().contains(never + ": stopped before the file appeared; no verdict"), err.toString());
        assertEquals("end of " + never + " (stopped: interrupted): 0 records, 0 compacted pairs; no verdict",
                out.toString().strip());
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
            StringWriter out = new StringWriter();
            StringWriter err = new StringWriter();
            CommandLine cl = Main.commandLine();
            cl.setOut(new PrintWriter(out, true));
            cl.setErr(new PrintWriter(err, true));
            AtomicInteger code = new AtomicInteger(-1);
            Thread watcher = new Thread(() -> code.set(cl.execute("watch", "--log", log.toString(),
                    "--models", models.toString())), "watch");
            watcher.start();
            Thread.sleep(delayMs);
            watcher.interrupt();
            watcher.join(10_000);
            assertFalse(watcher.isAlive());
            // whatever it had read by then decides the code; the point is a clean stop with its summary
            assertTrue(code.get() != ExitCodes.INTERNAL && !err.toString().contains("internal error"),
                    "interrupted after " + delayMs + " ms: exit " + code.get() + ": " + err);
            assertTrue(out.toString().startsWith("end of " + log + " (stopped: interrupted): "), out.toString());
        }
    }

    /** watch running in-process on {@code log}, its output captured; {@link #stop()} interrupts it. */
    private static final class Running {
        final StringWriter out = new StringWriter();
        final StringWriter err = new StringWriter();
        final AtomicInteger code = new AtomicInteger(-1);
        final Thread thread;

        Running(String... args) {
            CommandLine cl = Main.commandLine();
            cl.setOut(new PrintWriter(out, true));
            cl.setErr(new PrintWriter(err, true));
            thread = new Thread(() -> code.set(cl.execute(args)), "watch");
            thread.start();
        }

        int stop() throws InterruptedException {
            thread.interrupt();
            thread.join(10_000);
            assertFalse(thread.isAlive());
            return code.get();
        }
    }

    private Path learnTwoScenarios() throws Exception {
        Path logs = tmp.resolve("logs");
        Path models = tmp.resolve("models");
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", logs.toString(), "--models", models.toString()).code());
        return models;
    }

    /** Following a file with no monitor record: not a monitor log, said once, and a single log's watch exits 3. */
    @Test
    @Timeout(30)
    void followingSaysOnceWhenNothingRecognisableArrives() throws Exception {
        Path models = learnTwoScenarios();
        Path log = Files.writeString(tmp.resolve("syslog"), "");
        Running watch = new Running("watch", "--log", log.toString(), "--models", models.toString(), "--poll-ms", "5");
        String line = "May  1 10:00:00 host systemd[1]: Started Session 1 of user robot.\n";
        for (int i = 0; i < 6; i++) {
            Files.writeString(log, line.repeat(100), StandardOpenOption.APPEND);
            Thread.sleep(30);
        }
        await(() -> watch.err.toString().contains("not a monitor log?"), "says it");
        assertEquals(ExitCodes.BAD_INPUT, watch.stop(), watch.err.toString());
        List<String> err = watch.err.toString().lines().toList();
        assertEquals(1, err.stream().filter(l -> l.contains("not a monitor log?")).count(), watch.err.toString());
    }

    /**
     * What the real monitor prints when it starts, before the robot sends anything: the console capture's first lines
     * (colour codes as the monitor prints them, addresses of this fixture's own), in YARP 3.x's two forms.
     */
    static final String MONITOR_START = "Detected ABI qt5_12-x86_64, using ABI qt5_12-x86_64.\n"
            + "[\u001b[01;34mINFO\u001b[00m] |yarp.os.Port| Port /monitor active at tcp://10.0.0.7:10032/\n"
            + "[\u001b[01;34mINFO\u001b[00m] |\u001b[01;34myarp.os.impl.PortCoreInputUnit\u001b[00m|\u001b[31m"
            + "/monitor\u001b[00m| Receiving input from /GoToGoToClient/kitchen/monitor to /monitor using tcp\n"
            + "GammaRay server listening on: tcp://127.0.0.1:11732\n"
            + "[\u001b[01;34mINFO\u001b[00m] |yarp.os.impl.PortCoreInputUnit| Receiving input from /tick/monitor to "
            + "/monitor using tcp\n";

    /**
     * A monitor started before the robot: its log holds YARP's start-up lines and no record for longer than a file
     * that is not a log may go without one. It is followed on (said once), and the faulty run written later warns,
     * exit 1; nothing calls it "not a monitor log".
     */
    @Test
    @Timeout(60)
    void aMonitorStartedBeforeTheRobotIsFollowedUntilTheRobotRuns() throws Exception {
        Path models = learnTwoScenarios();
        Path log = Files.writeString(tmp.resolve("live.log"), MONITOR_START);
        Running watch = new Running("watch", "--log", log.toString(), "--models", models.toString(), "--poll-ms", "5");
        await(() -> watch.err.toString().contains("only YARP's start-up lines so far"), "says it: " + watch.err);
        Thread.sleep(1500); // past the moment a file of other lines would have been given up
        assertTrue(watch.thread.isAlive(), "still following: " + watch.err);
        Files.writeString(log, HandRuns.depleted().text(), StandardOpenOption.APPEND);
        await(() -> watch.out.toString().contains("WARNING"), "the robot's run is watched: " + watch.out + watch.err);
        assertEquals(ExitCodes.WARNING, watch.stop(), watch.err.toString());
        String err = watch.err.toString();
        assertFalse(err.contains("not a monitor log"), err);
        assertEquals(1, err.lines().filter(l -> l.contains("only YARP's start-up lines so far")).count(), err);
        assertTrue(err.contains(log + ": only YARP's start-up lines so far (3 lines such as 'Port /monitor active at"
                + " ...'), no monitor record yet: the monitor runs and waits for the robot; still watching"), err);
    }

    /** Lines of other programs beside YARP's, 1,000 of them without a record: not a monitor log after all. */
    @Test
    @Timeout(30)
    void yarpLinesDoNotMakeAThousandLinesOfAnotherProgramALog() throws Exception {
        Path models = learnTwoScenarios();
        Path log = Files.writeString(tmp.resolve("nav.log"), MONITOR_START
                + "[INFO] planner: replanning\n".repeat(1000));
        Running watch = new Running("watch", "--log", log.toString(), "--models", models.toString(), "--poll-ms", "5");
        await(() -> watch.err.toString().contains("not a monitor log?"), "says it: " + watch.err);
        assertEquals(ExitCodes.BAD_INPUT, watch.stop(), watch.err.toString());
    }

    /**
     * Interface messages no rule maps, while following: each command is reported at its first sighting, with its
     * line, and the totals by command come at the stop (follow mode used to drop them silently).
     */
    @Test
    @Timeout(30)
    void followingReportsUnmappedMessagesAtFirstSightingAndTotalsAtTheStop() throws Exception {
        Path models = learnTwoScenarios();
        Path log = tmp.resolve("run.log");
        Running watch = new Running("watch", "--log", log.toString(), "--models", models.toString(), "--poll-ms", "5");
        await(() -> watch.err.toString().contains("waiting for"), "waits for the log");
        Records camera = new Records().at(1).call("/camera/client", "/camera/server", "Camera", "grab", "", "frame")
                .call("/camera/client", "/camera/server", "Camera", "grab", "", "frame");
        Files.writeString(log, HandRuns.recharge().text() + camera.text());
        await(() -> watch.err.toString().contains("Camera/grab command"), "reports the first sighting");
        assertEquals(ExitCodes.OK, watch.stop(), watch.err.toString());
        String err = watch.err.toString();
        assertTrue(err.contains(log + ":" + (HandRuns.recharge().list().size() * 7 + 1)
                + ": warning: interface message no abstraction rule maps: Camera/grab command (first of its command"),
                err);
        assertEquals(1, err.lines().filter(l -> l.contains("first of its command")).count(), "not its reply: " + err);
        assertTrue(err.contains(log + ": warning: interface messages no rule maps: Camera/grab (4 messages): no rule "
                + "for this command"), err);
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
