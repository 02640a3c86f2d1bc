package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A logger that pauses after a rename rotation, longer than the quiet time, while a little is written to the new file,
 * then goes on writing the rest of its run to the renamed file: the monitor gets the very events that watching the
 * whole run in one file gives, warning and violation included, at the same lines, also when the pause cut a record,
 * or a line, in two.
 */
class RenamedLogWrittenOnTest {

    private static final Abstraction ABSTRACTION = AbstractionFiles.defaults();
    private static final Duration QUIET = Duration.ofMillis(50);
    /** Another program's lines in the new file: no record. */
    private static final String A_LITTLE = "yarprun: starting the logger\nyarprun: ok\n";

    private static ModelSet models;
    private static String run;

    @TempDir
    Path dir;

    @BeforeAll
    static void load() throws Exception {
        models = ModelStore.read(Path.of("models"), ABSTRACTION);
        run = LogWriter.toText(Simulator.run(Scenario.DEPLETED, 9001, SimOptions.defaults()), SimOptions.defaults());
    }

    @Test
    void theRestOfARunWrittenToTheRenamedFileGivesTheEventsOfTheWholeRun() throws Exception {
        List<String> whole = oneFile();
        int cut = lineStart(warningLine(whole) / 2); // a line boundary, inside a record, well before the warning
        assertEquals(whole, rotatedAt(cut));
    }

    @Test
    void aRecordCutInTheMiddleOfALineAtThePauseIsCompletedInTheRenamedFile() throws Exception {
        List<String> whole = oneFile();
        int cut = lineStart(warningLine(whole) / 2) + 7; // in the middle of a field line
        assertEquals(whole, rotatedAt(cut));
    }

    /** Events watching the whole run in one file gives; it warns and is violated. */
    private List<String> oneFile() throws IOException {
        Path log = Files.writeString(dir.resolve("whole.log"), run);
        List<String> events = new ArrayList<>();
        try (LogWatcher w = watcher(log, events)) {
            w.poll();
        }
        assertTrue(events.stream().anyMatch(e -> e.startsWith("Warning")), events.toString());
        assertTrue(events.stream().anyMatch(e -> e.startsWith("Violation")), events.toString());
        return events;
    }

    /**
     * The run written to {@code live.log} up to byte {@code cut}; then renamed, an empty log created and a little
     * written to it; after more than the quiet time (the watcher has turned to the new file) the writer goes on with
     * the rest in the renamed file.
     */
    private List<String> rotatedAt(int cut) throws Exception {
        Path log = dir.resolve("live.log");
        byte[] bytes = run.getBytes(StandardCharsets.UTF_8);
        List<String> events = new ArrayList<>();
        try (OutputStream logger = Files.newOutputStream(log, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
             LogWatcher w = watcher(log, events)) {
            logger.write(bytes, 0, cut);
            logger.flush();
            w.poll();
            Files.move(log, dir.resolve("live.log.1"));
            Files.writeString(log, A_LITTLE);
            w.poll();
            Thread.sleep(QUIET.toMillis() * 3);
            w.poll();
            assertFalse(w.replacing(), "turned to the new file");
            assertTrue(w.readingRenamed(), "the renamed file is read on");
            assertFalse(events.stream().anyMatch(e -> e.startsWith("Warning")), "no warning before the rest");
            logger.write(bytes, cut, bytes.length - cut);
            logger.flush();
            w.poll();
            assertEquals(java.util.Optional.empty(), w.takeNotice(), "one writer: nothing to tell");
        }
        return events;
    }

    private LogWatcher watcher(Path log, List<String> events) {
        PredictiveMonitor monitor = new PredictiveMonitor(models, ABSTRACTION, 0, ABSTRACTION.confirm(),
                e -> events.add(e.getClass().getSimpleName() + " " + e));
        return new LogWatcher(log, monitor, p -> events.add("Problem " + p), r -> { }, QUIET);
    }

    private static long warningLine(List<String> events) {
        String w = events.stream().filter(e -> e.startsWith("Warning")).findFirst().orElseThrow();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("line=(\\d+)").matcher(w);
        assertTrue(m.find(), w);
        return Long.parseLong(m.group(1));
    }

    /** The byte offset where line {@code n} (1-based) of the run begins. */
    private static int lineStart(long n) {
        int at = 0;
        for (long i = 1; i < n; i++) {
            at = run.indexOf('\n', at) + 1;
        }
        return run.substring(0, at).getBytes(StandardCharsets.UTF_8).length;
    }
}
