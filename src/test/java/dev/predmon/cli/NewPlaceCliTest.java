package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A robot sent to a place no training run went to. The abstraction cannot name its messages, so the trace misses
 * those steps, and a nominal machine that fails on the gap says nothing of a fault: the run is novel from the first
 * message about the place, and the forecast, not the thesis's elimination, decides whether to warn. Models learned
 * from 30 clean runs per scenario (with these, before the run was marked novel, most such recharge runs were warned
 * at about 44% battery because every nominal machine was eliminated while the faulty one still matched).
 */
class NewPlaceCliTest {

    @TempDir
    static Path tmp;
    static Path models;

    @BeforeAll
    static void learn() {
        Path logs = tmp.resolve("train");
        String[][] scenarios = {{"depleted", "100"}, {"direct", "1100"}, {"recharge", "2100"}};
        for (String[] s : scenarios) {
            Cli r = Cli.run("simulate", "--scenario", s[0], "--seed", s[1], "--runs", "30", "--out-dir",
                    logs.resolve(s[0]).toString());
            assertEquals(0, r.code(), r.err());
        }
        models = tmp.resolve("models");
        Cli r = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString());
        assertEquals(0, r.code(), r.err());
    }

    private static List<JsonNode> watchAtANewPlace(String scenario, int seed) throws Exception {
        Path log = tmp.resolve(scenario + "-" + seed + ".log");
        Cli sim = Cli.run("simulate", "--scenario", scenario, "--seed", Integer.toString(seed), "--new-location",
                "office", "--out", log.toString());
        assertEquals(0, sim.code(), sim.err());
        return Cli.run("watch", "--no-follow", "--json", "--log", log.toString(), "--models", models.toString())
                .jsonLines();
    }

    private static long firstLineAbout(Path log, String place) throws Exception {
        List<String> lines = Files.readAllLines(log);
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).contains(place)) {
                return i + 1L;
            }
        }
        throw new AssertionError("no line names " + place);
    }

    @Test
    void aRechargeRunToANewPlaceIsNovelAndNotWarned() throws Exception {
        for (int seed = 2; seed <= 5; seed++) {
            List<JsonNode> events = watchAtANewPlace("recharge", seed);
            String all = events.toString();
            assertFalse(events.stream().anyMatch(e -> e.get("event").asText().equals("warning")),
                    "seed " + seed + ": a safe run that went elsewhere is no fault: " + all);
            JsonNode end = events.get(events.size() - 1);
            assertEquals("end", end.get("event").asText(), "a new place alone still gets a verdict: " + all);
            long place = firstLineAbout(tmp.resolve("recharge-" + seed + ".log"), "office");
            long novel = end.get("forecast").get("novelSince").asLong();
            assertTrue(novel >= place - 8 && novel <= place,
                    "seed " + seed + ": novel from the first message about the place (line " + place + "), not "
                            + novel + ": " + end);
        }
    }

    @Test
    void aDepletedRunToANewPlaceIsStillWarnedBeforeItsViolation() throws Exception {
        for (int seed = 2; seed <= 3; seed++) {
            List<JsonNode> events = watchAtANewPlace("depleted", seed);
            JsonNode warning = events.stream().filter(e -> e.get("event").asText().equals("warning")).findFirst()
                    .orElseThrow(() -> new AssertionError("not warned: " + events));
            JsonNode violation = events.stream().filter(e -> e.get("event").asText().equals("violation"))
                    .findFirst().orElseThrow();
            assertTrue(warning.get("time").asDouble() < violation.get("time").asDouble(), warning.toString());
            assertTrue(warning.get("forecast").get("novelSince").isNumber(), warning.toString());
        }
    }
}
