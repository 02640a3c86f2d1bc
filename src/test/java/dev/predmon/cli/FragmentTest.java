package dev.predmon.cli;

import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A fragment of a log amid other bytes (a 3 KB piece of a monitor log between random bytes) is no evidence: the
 * records in it are a few seconds of a run, and every model "matches" so little. verify said "matches", explain that
 * the property holds, with exit 0. Every command now says how much of the file was records and gives no verdict.
 */
class FragmentTest {

    private static final Path MODELS = Path.of("models");

    @TempDir
    Path tmp;

    @Test
    void aFragmentAmidRandomBytesGetsNoVerdictAndSaysHowMuchWasRead() throws Exception {
        byte[] run = FleetWatchTest.run(Scenario.DEPLETED, 9001).getBytes(StandardCharsets.UTF_8);
        Random random = new Random(3);
        ByteArrayOutputStream file = new ByteArrayOutputStream();
        byte[] junk = new byte[100_000];
        random.nextBytes(junk);
        file.write(junk);
        file.write(Arrays.copyOfRange(run, run.length / 2, run.length / 2 + 3000));
        random.nextBytes(junk);
        file.write(junk);
        Path log = Files.write(tmp.resolve("fragment.log"), file.toByteArray());

        List<Cli> runs = List.of(Cli.run("verify", "--log", log.toString(), "--models", MODELS.toString(),
                        "--scenario", "depleted"),
                Cli.run("explain", "--log", log.toString(), "--models", MODELS.toString()),
                Cli.run("classify", "--log", log.toString(), "--models", MODELS.toString()),
                Cli.run("watch", "--no-follow", "--log", log.toString(), "--models", MODELS.toString()));
        for (Cli r : runs) {
            assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
            assertEquals("", r.out());
            List<String> about = r.err().lines().filter(l -> l.contains("fragment.log")).toList();
            assertEquals(1, about.size(), "one line, no list of parse problems: " + r.err());
            String err = about.get(0);
            assertTrue(err.matches("predmon: .*fragment\\.log: only \\d+ monitor records in \\d+ lines \\(about \\d+% of "
                    + "the file\\); a file that is mostly not a monitor log is no evidence: no verdict"), err);
        }
    }

    @Test
    void aWholeLogWithOtherProgramsLinesBetweenItsRecordsIsJudged() throws Exception {
        // the simulator's noisiest variant: YARP's own lines and the raw bottles between records
        Path log = tmp.resolve("run.log");
        assertEquals(ExitCodes.OK, Cli.run("simulate", "--scenario", "recharge", "--seed", "4", "--raw-lines",
                "--out", log.toString()).code());
        Cli r = Cli.run("classify", "--log", log.toString(), "--models", MODELS.toString());
        assertEquals(ExitCodes.OK, r.code(), r.err());
    }

    /**
     * A complete faulty run in a capture where another program wrote 8 lines between every two records: the records
     * are under half of the lines, but spread from end to end. {@code --no-follow} warned, then said "no verdict"
     * with exit 3, while following it gave exit 1; both now judge it the same, as does classify.
     */
    @Test
    void aWholeRunWithMoreLinesOfAnotherProgramThanRecordsGetsOneVerdictFollowedOrNot() throws Exception {
        StringBuilder text = new StringBuilder();
        for (String line : FleetWatchTest.run(Scenario.DEPLETED, 9001).split("\n", -1)) {
            if (!line.isEmpty() && Character.isDigit(line.charAt(0))) {
                for (int k = 0; k < 8; k++) {
                    text.append("[other] status line ").append(k).append('\n');
                }
            }
            text.append(line).append('\n');
        }
        Path log = Files.writeString(tmp.resolve("shared.log"), text);
        Cli once = Cli.run("watch", "--no-follow", "--log", log.toString(), "--models", MODELS.toString());
        assertEquals(ExitCodes.WARNING, once.code(), once.out() + once.err());
        assertTrue(once.out().contains("end of " + log + ": ") && once.out().contains("; battery VIOLATED, warned "), once.out());
        assertEquals(ExitCodes.WARNING, Cli.run("classify", "--log", log.toString(), "--models", MODELS.toString())
                .code());
        Cli.Running followed = Cli.start("watch", "--log", log.toString(), "--models", MODELS.toString());
        FleetWatchTest.await(() -> followed.out().toString().contains("VIOLATION"), "read to the violation");
        followed.stop();
        assertEquals(ExitCodes.WARNING, followed.code().get(), followed.out() + "\n" + followed.err());
    }
}
