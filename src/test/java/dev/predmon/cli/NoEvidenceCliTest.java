package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import dev.predmon.support.Records;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * No verdict on zero evidence: a file with no monitor record, or with records none of which the abstraction maps,
 * gets exit 3 and one line from watch, verify, classify and explain, never "matches scenario direct", "best match:
 * direct" or "the safety property holds".
 */
class NoEvidenceCliTest {

    @TempDir
    Path tmp;
    Path models;

    @BeforeEach
    void learn() throws Exception {
        Path logs = tmp.resolve("logs");
        models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(logs, models, "direct");
    }

    private List<Cli> allFour(Path log) {
        String l = log.toString();
        String m = models.toString();
        List<Cli> runs = new ArrayList<>();
        runs.add(Cli.run("watch", "--no-follow", "--log", l, "--models", m));
        runs.add(Cli.run("verify", "--scenario", "direct", "--log", l, "--models", m));
        runs.add(Cli.run("classify", "--log", l, "--models", m));
        runs.add(Cli.run("explain", "--log", l, "--models", m));
        runs.add(Cli.run("classify", "--json", "--log", l, "--models", m));
        return runs;
    }

    /** Every command: exit 3, nothing on stdout (no verdict), one stderr line naming the log and saying {@code what}. */
    private void noVerdict(Path log, String what) {
        for (Cli r : allFour(log)) {
            assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
            assertEquals("", r.out(), "no verdict");
            List<String> lines = r.err().strip().lines().toList();
            assertEquals(1, lines.size(), r.err());
            assertTrue(lines.get(0).startsWith("predmon: " + log + ": ") && lines.get(0).contains(what), r.err());
        }
    }

    @Test
    void aSystemLogOfAnotherProgram() throws Exception {
        StringBuilder dpkg = new StringBuilder();
        for (int i = 0; i < 40; i++) {
            dpkg.append("2024-05-0").append(1 + i % 9).append(" 10:00:0").append(i % 10)
                    .append(" status installed libc6:amd64 2.36-9\n");
        }
        Path log = Files.writeString(tmp.resolve("dpkg.log"), dpkg);
        noVerdict(log, "no YARP monitor record in 40 lines; is this a monitor log?");
    }

    /**
     * The README given as the log to the shipped models, which have a scorecard: the one line comes alone, not
     * after the scorecard, which would read as if the models had judged something.
     */
    @Test
    void aReadmeWithModelsThatHaveAScorecard() {
        Path readme = Path.of("README.md");
        Cli r = Cli.run("watch", "--no-follow", "--log", readme.toString(), "--models", "models");
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
        assertEquals("", r.out());
        List<String> lines = r.err().strip().lines().toList();
        assertEquals(1, lines.size(), r.err());
        assertTrue(lines.get(0).startsWith("predmon: " + readme + ": no YARP monitor record in ")
                && lines.get(0).contains("; is this a monitor log?"), r.err());
    }

    @Test
    void anEmptyFile() throws Exception {
        noVerdict(Files.writeString(tmp.resolve("empty.log"), ""), "no YARP monitor record in 0 lines");
    }

    /** Two lines that start a record and stop: the line names the problem it met. */
    @Test
    void aTwoLineFile() throws Exception {
        Path log = Files.writeString(tmp.resolve("two.log"), "1.000000\tDEBUG\tCommand intercepted:\n  From      : /x\n");
        noVerdict(log, "no YARP monitor record in 2 lines; is this a monitor log? (first problem: line 1:");
    }

    @Test
    void randomBytes() throws Exception {
        byte[] bytes = new byte[16 * 1024];
        new Random(9).nextBytes(bytes);
        noVerdict(Files.write(tmp.resolve("random.bin"), bytes), "no YARP monitor record in ");
    }

    /** A real executable, as {@code --log /usr/bin/java}. */
    @Test
    void anExecutable() {
        noVerdict(Path.of(System.getProperty("java.home"), "bin", "java"), "no YARP monitor record in ");
    }

    /** Monitor records, but of a component the abstraction does not know: said, with what was seen. */
    @Test
    void recordsNoneOfWhichTheAbstractionMaps() throws Exception {
        Path log = Files.writeString(tmp.resolve("camera.log"), new Records()
                .call("/camera/client", "/camera/server", "Camera", "grab", "", "frame").text());
        noVerdict(log, "no skill-component interface message the abstraction 'thesis-tables-4.1-4.2-bands-5.2' maps "
                + "in 2 records (only Camera/grab command, Camera/grab reply 'frame'); no verdict");
    }

    /** Commands the abstraction maps but no reply to any of them: no pair, no verdict. */
    @Test
    void commandsWithoutReplies() throws Exception {
        String run = HandRuns.recharge().text();
        StringBuilder commands = new StringBuilder();
        for (String record : run.split("(?=\\d+\\.\\d+\\tDEBUG\\t)", -1)) {
            if (record.contains("Command intercepted")) {
                commands.append(record);
            }
        }
        Path log = Files.writeString(tmp.resolve("commands.log"), commands);
        noVerdict(log, "interface message(s) the abstraction 'thesis-tables-4.1-4.2-bands-5.2' maps, but no complete "
                + "query/reply pair");
    }

    /** A log with a run in it still gets its verdict: the check is not in the way. */
    @Test
    void aRealRunStillGetsItsVerdict() throws Exception {
        Path log = Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text());
        for (Cli r : allFour(log)) {
            assertTrue(r.code() == ExitCodes.OK || r.code() == ExitCodes.WARNING, r.err());
            assertTrue(!r.out().isBlank() && r.err().isBlank(), r.out() + r.err());
        }
    }
}
