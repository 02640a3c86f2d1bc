package dev.predmon.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.BufferedReader;
import java.io.File;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * A write to standard output that fails is an error, not a success: a full disk behind {@code >} left a truncated
 * log or report with exit 0, and a {@code watch --json} whose reader had gone followed for ever. Real child
 * processes, since only there is standard output a file descriptor that can fail.
 */
class StdoutFailureTest {

    private static final File FULL = new File("/dev/full");
    private static final String NO_SPACE = "predmon: standard output: not written (no space left on device); what it "
            + "shows is incomplete";

    @TempDir
    Path tmp;

    /** {@code predmon ARGS > /dev/full}: exit 3 and exactly the one line. */
    private static void intoAFullDisk(String... args) throws Exception {
        assumeTrue(FULL.exists(), "no /dev/full");
        Path err = Files.createTempFile("predmon-err", ".txt");
        try {
            Process p = new ProcessBuilder(Child.command(args)).redirectOutput(FULL).redirectError(err.toFile()).start();
            assertTrue(p.waitFor(120, TimeUnit.SECONDS), "finished");
            String text = Files.readString(err);
            assertEquals(ExitCodes.BAD_INPUT, p.exitValue(), text);
            assertEquals(List.of(NO_SPACE), text.strip().lines().toList());
        } finally {
            Files.delete(err);
        }
    }

    @Test
    void simulateIntoAFullDisk() throws Exception {
        intoAFullDisk("simulate", "--scenario", "depleted", "--seed", "3");
    }

    @Test
    void abstractionShowIntoAFullDisk() throws Exception {
        intoAFullDisk("abstraction", "show", "thesis");
    }

    @Test
    void evaluateJsonIntoAFullDisk() throws Exception {
        Path logs = tmp.resolve("logs");
        for (String scenario : List.of("direct", "depleted")) {
            Path from = Path.of("sample-logs", scenario);
            Path to = Files.createDirectories(logs.resolve(scenario));
            for (String name : List.of("scenario.json", scenario + "-1.log", scenario + "-2.log")) {
                Files.copy(from.resolve(name), to.resolve(name));
            }
        }
        intoAFullDisk("evaluate", "--logs", logs.toAbsolutePath().toString(), "--folds", "2", "--json");
    }

    /**
     * The reader of {@code watch --json} goes away: the next event is a write to a broken pipe, and watch stops
     * (it followed for ever), exit 3 with one line.
     */
    @Test
    void watchStopsWhenItsReaderIsGone() throws Exception {
        Path log = tmp.resolve("robot.log");
        Files.copy(Path.of("sample-logs", "direct", "direct-1.log"), log);
        Process p = new ProcessBuilder(Child.command("watch", "--json", "--models",
                Path.of("models").toAbsolutePath().toString(), "--log", log.toString()))
                .redirectError(tmp.resolve("err.txt").toFile()).start();
        try {
            BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
            assertNotNull(out.readLine(), "watch printed its first event");
            p.getInputStream().close(); // the reader is gone
            byte[] more = Files.readAllBytes(Path.of("sample-logs", "depleted", "depleted-1.log"));
            for (int i = 0; i < 20 && !p.waitFor(500, TimeUnit.MILLISECONDS); i++) {
                Files.write(log, more, StandardOpenOption.APPEND); // events to write, into the broken pipe
            }
            assertTrue(p.waitFor(20, TimeUnit.SECONDS), "watch stopped");
            String err = Files.readString(tmp.resolve("err.txt"));
            assertEquals(ExitCodes.BAD_INPUT, p.exitValue(), err);
            assertTrue(err.strip().endsWith("predmon: standard output: not written (broken pipe); what it shows is "
                    + "incomplete"), err);
        } finally {
            p.destroyForcibly();
        }
    }

    /** Nothing changes where standard output takes everything. */
    @Test
    void aWorkingStandardOutputIsUnchanged() throws Exception {
        Child r = Child.run(tmp, "abstraction", "show", "thesis");
        assertEquals(ExitCodes.OK, r.code(), r.err());
        assertEquals("", r.err());
        assertTrue(r.out().contains("\"rules\""), r.out());
    }
}
