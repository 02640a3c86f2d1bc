package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;
import dev.predmon.ros2.TopicMapping;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.simulate.Nav2Recording;
import dev.predmon.simulate.Novelties;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code simulate --format mcap|sqlite3}: a simulated run written as an MCAP and as a sqlite3 file reads back, with
 * {@code nav2}, to exactly the records its messages map to before they were written, line by line; so every stage
 * above (forecasts, warnings, verdicts) sees the same run from either file.
 */
class SimulatedBagsTest {

    private static final Abstraction NAV2 = AbstractionFiles.builtin("nav2").orElseThrow();

    @TempDir
    Path dir;

    private static List<LogRecord> read(Path file) throws IOException {
        List<LogRecord> records = new ArrayList<>();
        List<String> problems = new ArrayList<>();
        try (RecordSource s = NAV2.format().read(file, RecordSink.of(records::add, p -> problems.add(p.message())))) {
            s.drain();
        }
        assertEquals(List.of(), problems);
        return records;
    }

    @Test
    void bothFormsReadBackToTheRecordsOfTheMessagesWritten() throws IOException {
        SimOptions aborting = SimOptions.defaults().withNovelties(Novelties.NONE.withAborts(1, Novelties.AbortOn.ANY));
        for (Scenario s : Scenario.values()) {
            SimRun run = Simulator.run(s, 7, s == Scenario.DIRECT ? aborting : SimOptions.defaults());
            List<LogRecord> expected = new ArrayList<>();
            TopicMapping mapping = new TopicMapping(NAV2.topicRules());
            for (BagMessage m : Nav2Recording.of(run)) {
                mapping.map(m, expected::add);
            }
            assertTrue(expected.size() > 50, s.id());
            for (SimulatedBags.Form form : List.of(SimulatedBags.Form.MCAP, SimulatedBags.Form.SQLITE3)) {
                Path file = dir.resolve(s.id() + form.extension);
                SimulatedBags.write(file, List.of(run), form, "{}\n");
                assertEquals(expected, read(file), s.id() + " as " + form);
                assertTrue(Files.exists(file.resolveSibling(file.getFileName() + ".truth.json")));
                assertFalse(Files.exists(file.resolveSibling("." + file.getFileName() + ".part")), "no leftover");
            }
        }
    }
}
