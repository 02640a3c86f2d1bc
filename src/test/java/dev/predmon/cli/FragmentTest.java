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
}
