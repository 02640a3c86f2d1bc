package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code watch} across log rotation, as logrotate does it. In its default mode ({@code create}) the log is renamed
 * and an empty one created while the robot's logger goes on writing to the renamed file until it reopens its log:
 * what it writes there is read, warning and violation included, before the new file. With {@code copytruncate}
 * the log is copied and emptied. Either way the end summary and the exit code cover every run watched since the
 * start, not only those after the last rotation.
 */
class RotationTest {

    private static final int RECORD_LINES = 7;

    @TempDir
    Path tmp;
    Path models;
    Path log;

    @BeforeEach
    void learn() throws Exception {
        models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(tmp.resolve("logs"), models, "recharge");
        log = tmp.resolve("run.log");
    }

    /** The first {@code n} records of a run's text, or from record {@code n} on when {@code rest}. */
    private static String records(String text, int n, boolean rest) {
        List<String> lines = text.lines().toList();
        List<String> part = rest ? lines.subList(n * RECORD_LINES, lines.size()) : lines.subList(0, n * RECORD_LINES);
        return String.join("\n", part) + "\n";
    }

    /**
     * An interface message no rule maps, {@code Probe/name} at time {@code t}: watch says so on stderr when it reads
     * it, so the test knows how far watch has read.
     */
    private static String probe(String name, double t) {
        return String.format(Locale.ROOT, "%.6f\tDEBUG\tCommand intercepted:%n", t) + "  From      : /probe\n"
                + "  To        : /probed\n  Protocol  : Probe\n  Command   : " + name + "\n  Arguments : \n"
                + "  Reply     : \n";
    }

    private static void read(Cli.Running w, String probe) throws InterruptedException {
        try {
            FleetWatchTest.await(() -> w.err().toString().contains("Probe/" + probe), "watch reads up to " + probe);
        } catch (AssertionError e) {
            throw new AssertionError(e.getMessage() + "; stderr: " + w.err() + "; stdout: " + w.out(), e);
        }
    }

    @Test
    @Timeout(60)
    void aRenamedLogStillWrittenIsReadToItsEndAndTheSummaryCoversEveryRun() throws Exception {
        String depleted = HandRuns.depleted().text();
        // (right after the tenth record: a pause before it would hold it back to see whether the tree restarted)
        Files.writeString(log, records(depleted, 10, false) + probe("first", 0.02));
        Cli.Running w = Cli.start("watch", "--log", log.toString(), "--models", models.toString(), "--poll-ms", "5");
        read(w, "first");

        Path rotated = tmp.resolve("run.log.1");
        Files.move(log, rotated);
        Files.writeString(log, ""); // logrotate's create: an empty log at once, the logger still at the old one
        Thread.sleep(300); // some 60 polls: time to notice the new file (and, before, to leave the old one at once)
        Files.writeString(rotated, records(depleted, 10, true), StandardOpenOption.APPEND);
        FleetWatchTest.await(() -> w.out().toString().contains("VIOLATION"), "the rest of the renamed log is read: "
                + w.out());
        assertTrue(w.out().toString().contains("WARNING: the run can only be faulty scenario depleted"), w.out().toString());

        // The logger reopens its log at last: a nominal run in the new file.
        Files.writeString(log, HandRuns.recharge().text() + probe("second", 70.01), StandardOpenOption.APPEND);
        read(w, "second");
        assertTrue(w.out().toString().contains("the log was replaced: monitoring starts over"), w.out().toString());
        w.stop();
        String out = w.out().toString();
        assertEquals(ExitCodes.WARNING, w.code().get(), "the warning before the rotation counts: " + out + w.err());
        List<String> lines = out.lines().toList();
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("run 0 (from line 1): ")
                && l.contains("; battery VIOLATED, warned 30.000 s before")), out);
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("run 1 (from line 1, after the log was replaced): ")
                && l.contains("; no warning; ") && !l.contains("VIOLATED")), out);
        String end = lines.get(lines.size() - 1);
        assertTrue(end.startsWith("end of " + log + " (stopped: interrupted): ") && end.contains(" 2 runs, ")
                && end.contains("; battery VIOLATED, warned "), end);
    }

    @Test
    @Timeout(60)
    void aWarningThenCopytruncateThenANominalRunStillExitsWithTheWarning() throws Exception {
        Files.writeString(log, HandRuns.depleted().text() + probe("first", 95.0));
        Cli.Running w = Cli.start("watch", "--log", log.toString(), "--models", models.toString(), "--poll-ms", "5",
                "--json");
        read(w, "first");
        assertTrue(w.out().toString().contains("\"event\":\"warning\""), w.out().toString());

        Files.copy(log, tmp.resolve("run.log.1"), StandardCopyOption.REPLACE_EXISTING);
        try (FileChannel truncate = FileChannel.open(log, StandardOpenOption.WRITE)) {
            truncate.truncate(0);
        }
        FleetWatchTest.await(() -> w.out().toString().contains("\"event\":\"restarted\""), "the truncation is seen");
        Files.writeString(log, HandRuns.recharge().text() + probe("second", 70.01), StandardOpenOption.APPEND);
        read(w, "second");
        w.stop();
        assertEquals(ExitCodes.WARNING, w.code().get(), w.out() + "\n" + w.err());
        List<String> lines = w.out().toString().strip().lines().toList();
        String end = lines.get(lines.size() - 1);
        assertTrue(end.startsWith("{\"event\":\"end\"") && end.contains("\"warning\":true")
                && end.contains("\"violation\":true"), end);
        assertTrue(end.contains("\"runs\":[{\"run\":0,\"line\":1,") && end.contains("{\"run\":1,\"line\":1,"), end);
        assertTrue(end.contains("\"records\":" + (HandRuns.depleted().list().size() + HandRuns.recharge().list().size()
                + 2) + ","), "every record since the start: " + end);
    }
}
