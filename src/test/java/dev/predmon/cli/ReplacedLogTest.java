package dev.predmon.cli;

import dev.predmon.simulate.Scenario;
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

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * {@code watch} when a log's path comes to hold something other than the next written file: two rename rotations
 * before the logger reopens (an empty file between), a FIFO, a directory. The file now at the path is read, nothing
 * blocks, one line names the log, the other logs of the fleet are watched on, and a warning already raised keeps its
 * exit code, with the {@code end} of every log printed.
 */
class ReplacedLogTest {

    private static final Path MODELS = Path.of("models");

    @TempDir
    Path dir;

    /**
     * {@code exec 3>>live.log; mv live.log live.log.1; : >live.log; mv live.log live.log.2; : >live.log; cat dep.log
     * >>live.log}: the depleted run now at the path warns (it was never read: exit 0).
     */
    @Test
    @Timeout(90)
    void twoRenamesBeforeTheLoggerReopensThenAFaultyRunWarns() throws Exception {
        // an interface message no rule maps: watch says so when it has read it, so the test knows it is following
        Path log = Files.writeString(dir.resolve("live.log"), probe("first"));
        Cli.Running w = Cli.start("watch", "--log", log.toString(), "--models", MODELS.toString());
        try (OutputStream held = Files.newOutputStream(log, StandardOpenOption.APPEND)) { // exec 3>>live.log
            FleetWatchTest.await(() -> w.err().toString().contains("Probe/first"), "watch follows: " + w.err());
            Files.move(log, dir.resolve("live.log.1"));
            Files.writeString(log, "");
            Thread.sleep(300); // watch sees the empty file and holds it open
            Files.move(log, dir.resolve("live.log.2"));
            Files.writeString(log, "");
            Thread.sleep(300);
            Files.writeString(log, FleetWatchTest.run(Scenario.DEPLETED, 9001), StandardOpenOption.APPEND);
            FleetWatchTest.await(() -> w.out().toString().contains("VIOLATION"), "the run now at the path is read: "
                    + w.out() + w.err());
        }
        w.stop();
        assertEquals(ExitCodes.WARNING, w.code().get(), w.out() + "\n" + w.err());
        assertTrue(w.out().toString().contains("WARNING"), w.out().toString());
    }

    /**
     * A fleet: robot-1 warns, then its log is replaced by a FIFO, then by a directory; robot-2's run comes after
     * and its warning arrives. One line names robot-1 each time, and both get their {@code end}; exit 1.
     */
    @Test
    @Timeout(90)
    void aLogReplacedByAFifoThenADirectoryStopsNothing() throws Exception {
        Path robots = Files.createDirectories(dir.resolve("robots"));
        Path one = Files.writeString(robots.resolve("robot-1.log"), FleetWatchTest.run(Scenario.DEPLETED, 9001));
        Path two = Files.writeString(robots.resolve("robot-2.log"), "");
        Cli.Running w = Cli.start("watch", "--log", robots.toString(), "--models", MODELS.toString());
        try {
            FleetWatchTest.await(() -> w.out().toString().contains(one + ": ") && w.out().toString().contains(
                    "VIOLATION"), "robot-1's run: " + w.out());
            Files.delete(one);
            assumeTrue(mkfifo(one), "no mkfifo here");
            FleetWatchTest.await(() -> w.err().toString().contains(one + ": is a FIFO, not a regular file"),
                    "says what is at robot-1's path: " + w.err());
            Files.writeString(two, FleetWatchTest.run(Scenario.DEPLETED, 9002), StandardOpenOption.APPEND);
            FleetWatchTest.await(() -> w.out().toString().lines().anyMatch(l -> l.startsWith(two + ": ")
                    && l.contains("WARNING")), "robot-2 is still watched: " + w.out() + w.err());
            Files.delete(one);
            Files.createDirectory(one);
            FleetWatchTest.await(() -> w.err().toString().contains(one + ": is a directory, not a regular file"),
                    "says what is at robot-1's path: " + w.err());
            w.stop();
        } finally {
            unblock(one);
        }
        assertEquals(ExitCodes.WARNING, w.code().get(), w.out() + "\n" + w.err());
        List<String> about = w.err().toString().lines().filter(l -> l.contains("robot-1")).toList();
        assertEquals(List.of("predmon: " + one + ": is a FIFO, not a regular file; watching for a log file there",
                "predmon: " + one + ": is a directory, not a regular file; watching for a log file there"), about);
        String out = w.out().toString();
        assertTrue(out.contains("end of " + one + " (stopped: interrupted): ") && out.contains("end of " + two
                + " (stopped: interrupted): "), out);
    }

    /**
     * The recipe of a logger that pauses after a rename rotation: the log is renamed and an empty one created, a little
     * is written to the new file, and 1.5 s later (watch has turned to the new file) the old writer goes on in the
     * renamed file with the rest of a faulty run. Its warning and violation arrive, and the exit code is the whole
     * run's (1).
     */
    @Test
    @Timeout(90)
    void aLoggerGoingOnInTheRenamedFileAfterTheTurnIsRead() throws Exception {
        Path log = dir.resolve("live.log");
        String run = FleetWatchTest.run(Scenario.DEPLETED, 9001);
        int half = run.indexOf("intercepted", run.length() / 8); // inside a record, before the warning
        Cli.Running w;
        try (OutputStream held = Files.newOutputStream(log, StandardOpenOption.CREATE, StandardOpenOption.APPEND)) {
            held.write(run.substring(0, half).getBytes(StandardCharsets.UTF_8));
            held.flush();
            w = Cli.start("watch", "--log", log.toString(), "--models", MODELS.toString());
            FleetWatchTest.await(() -> w.err().toString().contains("following " + log), "watch follows: " + w.err());
            Files.move(log, dir.resolve("live.log.1"));
            Files.writeString(log, "yarprun: starting\n");
            Thread.sleep(1500);
            assertTrue(!w.out().toString().contains("WARNING"), "nothing to warn of yet: " + w.out());
            held.write(run.substring(half).getBytes(StandardCharsets.UTF_8));
            held.flush();
            FleetWatchTest.await(() -> w.out().toString().contains("VIOLATION"), "the rest of the run is read: "
                    + w.out() + w.err());
        }
        w.stop();
        assertEquals(ExitCodes.WARNING, w.code().get(), w.out() + "\n" + w.err());
        assertTrue(w.out().toString().contains("WARNING"), w.out().toString());
    }

    /**
     * A fleet ({@code watch --log DIR}): robot-1's logger goes on in its renamed file after watch turned to the new
     * one, and its warning arrives; robot-2's faulty run, written meanwhile, is warned of too.
     */
    @Test
    @Timeout(90)
    void inAFleetTheRenamedFileIsReadAndTheOtherRobotsAreStillWarned() throws Exception {
        Path robots = Files.createDirectories(dir.resolve("robots"));
        Path one = robots.resolve("robot-1.log");
        // robot-2's log begins with a message no rule maps, which watch names once it has read it (after robot-1)
        Path two = Files.writeString(robots.resolve("robot-2.log"), probe("first"));
        String run = FleetWatchTest.run(Scenario.DEPLETED, 9001);
        int half = run.indexOf("intercepted", run.length() / 8);
        Cli.Running w;
        try (OutputStream held = Files.newOutputStream(one, StandardOpenOption.CREATE, StandardOpenOption.APPEND)) {
            held.write(run.substring(0, half).getBytes(StandardCharsets.UTF_8));
            held.flush();
            w = Cli.start("watch", "--log", robots.toString(), "--models", MODELS.toString());
            FleetWatchTest.await(() -> w.err().toString().contains("Probe/first"), "watch follows: " + w.err());
            Files.move(one, robots.resolve("robot-1.log.1"));
            Files.writeString(one, "yarprun: starting\n");
            Thread.sleep(1500);
            held.write(run.substring(half).getBytes(StandardCharsets.UTF_8));
            held.flush();
            Files.writeString(two, FleetWatchTest.run(Scenario.DEPLETED, 9002), StandardOpenOption.APPEND);
            FleetWatchTest.await(() -> warned(w, one) && warned(w, two), "both robots warned: " + w.out() + w.err());
        }
        w.stop();
        assertEquals(ExitCodes.WARNING, w.code().get(), w.out() + "\n" + w.err());
    }

    private static boolean warned(Cli.Running w, Path log) {
        return w.out().toString().lines().anyMatch(l -> l.startsWith(log + ": ") && l.contains("WARNING"));
    }

    /**
     * Two writers: the new file gets records, and then the old logger goes on in the renamed file. Its records are
     * read too, and one line says that the two are read as one run.
     */
    @Test
    @Timeout(90)
    void twoWritersAfterARenameAreReadAndToldOf() throws Exception {
        Path log = Files.writeString(dir.resolve("live.log"), probe("first"));
        Cli.Running w = Cli.start("watch", "--log", log.toString(), "--models", MODELS.toString());
        try (OutputStream held = Files.newOutputStream(log, StandardOpenOption.APPEND)) {
            FleetWatchTest.await(() -> w.err().toString().contains("Probe/first"), "watch follows: " + w.err());
            Files.move(log, dir.resolve("live.log.1"));
            Files.writeString(log, probe("second"));
            FleetWatchTest.await(() -> w.err().toString().contains("Probe/second"), "the new file is taken up");
            held.write(probe("third").getBytes(StandardCharsets.UTF_8));
            held.flush();
            FleetWatchTest.await(() -> w.err().toString().contains("Probe/third"), "the renamed file is read on: "
                    + w.err());
            FleetWatchTest.await(() -> w.err().toString().contains(log + ": the file renamed away at a rotation is "
                    + "still written after the file now at the path gave records"), "told: " + w.err());
        }
        w.stop();
    }

    /**
     * Two writers after a rename, as a red team found it: the robot's run goes on in the new file, the old writer adds
     * an aborted navigation to the renamed file (line 9,000 or so there), and the new file's run warns 2 s later at a
     * line of its own below that. The abort was read first: the violation came with no warning before it, exit 6.
     * Comparing lines across the two files gave exit 1, a warning "before" a violation it came after.
     */
    @Test
    @Timeout(90)
    void aViolationReadFromTheRenamedFileBeforeTheNewFilesWarningIsUnwarned() throws Exception {
        String run = FleetWatchTest.run(Scenario.DEPLETED, 9001);
        Path whole = Files.writeString(dir.resolve("whole.log"), run);
        Cli alone = Cli.run("watch", "--log", whole.toString(), "--models", MODELS.toString(), "--no-follow", "--json");
        long warnedAt = Cli.firstEvent(alone.jsonLines(), "warning").orElseThrow().get("line").asLong();
        String firstPart = lines(run, warnedAt / 2);
        Path log = Files.writeString(dir.resolve("live.log"), probe("first") + "yarprun: a line of another program\n"
                .repeat(9000));
        Cli.Running w = Cli.start("watch", "--log", log.toString(), "--models", MODELS.toString());
        try (OutputStream held = Files.newOutputStream(log, StandardOpenOption.APPEND)) {
            FleetWatchTest.await(() -> w.err().toString().contains("Probe/first"), "watch follows: " + w.err());
            Files.move(log, dir.resolve("live.log.1"));
            Files.writeString(log, firstPart + probe("second"));
            FleetWatchTest.await(() -> w.err().toString().contains("Probe/second"), "the new file is taken up");
            held.write(aborted(lastTime(firstPart)).getBytes(StandardCharsets.UTF_8)); // line 9008 of live.log.1
            held.flush();
            FleetWatchTest.await(() -> w.out().toString().contains("VIOLATION"), "the abort is read: " + w.out());
            assertFalse(w.out().toString().contains("WARNING"), "no warning yet: " + w.out());
            Files.writeString(log, run.substring(firstPart.length()), StandardOpenOption.APPEND);
            FleetWatchTest.await(() -> w.out().toString().contains("WARNING"), "the run warns: " + w.out());
        }
        w.stop();
        String out = w.out().toString();
        assertTrue(out.contains("line 9008"), out);
        assertEquals(ExitCodes.UNWARNED_VIOLATION, w.code().get(), out + "\n" + w.err());
    }

    /** The first {@code n} lines of {@code text}. */
    private static String lines(String text, long n) {
        int at = 0;
        for (long i = 0; i < n; i++) {
            at = text.indexOf('\n', at) + 1;
        }
        return text.substring(0, at);
    }

    /** The time of the last record of {@code text}, a log of the column layout. */
    private static String lastTime(String text) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(?m)^([0-9.]+)\tDEBUG").matcher(text);
        String last = null;
        while (m.find()) {
            last = m.group(1);
        }
        return last;
    }

    /** A navigation's status reply ABORT (3) at {@code time}: what "navigation never aborts" forbids. */
    private static String aborted(String time) {
        return time + "\tDEBUG\tReply intercepted:\n  From      : /GoToComponent\n  To        : /GoToGoToClient/kitchen\n"
                + "  Protocol  : GoTo\n  Command   : getStatus\n  Arguments : kitchen\n  Reply     : 3\n";
    }

    /** An interface message no rule maps: watch says so when it reads it. */
    private static String probe(String name) {
        return "0.000000\tDEBUG\tCommand intercepted:\n  From      : /probe\n  To        : /probed\n"
                + "  Protocol  : Probe\n  Command   : " + name + "\n  Arguments : \n  Reply     : \n";
    }

    static boolean mkfifo(Path path) throws InterruptedException {
        try {
            return new ProcessBuilder("mkfifo", path.toString()).inheritIO().start().waitFor() == 0;
        } catch (IOException e) {
            return false;
        }
    }

    /** Should a reader be stuck opening a FIFO there, a writer's open lets it go. */
    private static void unblock(Path fifo) {
        if (Files.isRegularFile(fifo) || Files.isDirectory(fifo) || !Files.exists(fifo)) {
            return;
        }
        Thread t = new Thread(() -> {
            try (OutputStream out = Files.newOutputStream(fifo)) {
                out.flush();
            } catch (IOException ignored) {
                // nothing was stuck after all
            }
        }, "unblock-fifo");
        t.setDaemon(true);
        t.start();
    }
}
