package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.parse.LogReader;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.StreamSupport;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A recharge run whose way to the charging station is lost for good: the simulated tree sends
 * {@code goTo(charging_station)} before the {@code halt(kitchen)} of the way it leaves, so the halt must not answer the
 * station's goTo. {@code watch} with the built-in abstraction reports navigation-in-time violated at the first tick
 * more than 400 ticks after that goTo, as the simulator's truth has it (the truth counts the deadline's own tick: its
 * violation is one tick earlier).
 */
class PreemptedNavigationCliTest {

    @TempDir
    Path dir;

    @Test
    void aWayToTheStationStuckPastItsDeadlineIsViolatedWhereTheTruthSays() throws Exception {
        for (int seed = 1; seed <= 2; seed++) {
            Path log = dir.resolve("stuck-" + seed + ".log");
            Cli sim = Cli.run("simulate", "--scenario", "recharge", "--seed", Integer.toString(seed),
                    "--never-arrives", "450", "--abort-on", "station", "--out", log.toString());
            assertEquals(0, sim.code(), sim.err());
            JsonNode truth = new ObjectMapper().readTree(Path.of(log + ".truth.json").toFile()).get("properties")
                    .get("navigation-in-time");
            assertTrue(truth.get("violated").asBoolean(), truth.toString());

            List<LogRecord> records = new ArrayList<>();
            LogReader.read(log, records::add, problem -> { });
            LogRecord goTo = records.stream().filter(r -> r.kind() == RecordKind.COMMAND && r.command().equals("goTo")
                    && r.arguments().equals("charging_station")).findFirst().orElseThrow();
            LogRecord halt = records.stream().filter(r -> r.kind() == RecordKind.COMMAND && r.command().equals("halt")
                    && r.arguments().equals("kitchen") && r.line() > goTo.line()).findFirst().orElseThrow();
            assertTrue(halt.line() > goTo.line(), "the case: the halt of the way left comes after the new goTo");
            // the first Tick after the truth's: the checker's deadline passes at more than 400 ticks
            long truthLine = truth.get("line").asLong();
            long expected = records.stream().filter(r -> r.kind() == RecordKind.TICK && r.line() > truthLine)
                    .findFirst().orElseThrow().line();

            Cli watch = Cli.run("watch", "--no-follow", "--json", "--log", log.toString(), "--models", "models",
                    "--abstraction", "thesis");
            JsonNode v = watch.jsonLines().stream().filter(e -> e.get("event").asText().equals("violation")
                    && e.path("property").asText().equals("navigation-in-time")).findFirst()
                    .orElseThrow(() -> new AssertionError("no navigation-in-time violation:\n" + watch.out()));
            assertEquals(expected, v.get("line").asLong(), v.toString());
            assertEquals("no getStatus 2 or halt in 400 ticks since goTo at line " + goTo.line(),
                    v.get("what").asText());
            JsonNode end = watch.jsonLines().stream().filter(e -> e.get("event").asText().equals("end")).findFirst()
                    .orElseThrow();
            JsonNode verdict = StreamSupport.stream(end.get("properties").spliterator(), false)
                    .filter(p -> p.get("property").asText().equals("navigation-in-time")).findFirst().orElseThrow();
            assertEquals("violated", verdict.get("verdict").asText(), verdict.toString());
            assertTrue(watch.code() == 1 || watch.code() == 6, "a warning (1) or a violation unwarned (6), never a"
                    + " clean exit: " + watch.code());
        }
    }
}
