package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.support.SimulatedSets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A safe run that goes a little lower than every safe training run: 12 runs per scenario (seeds 501-512), and a
 * recharge run (seed 7034) that reaches the charging station at 31%, below the lowest recharge run in training.
 * Counted as "12 of 12 training runs that went as low violated", it was warned at P 0.99; a new safe run falls below
 * all of the n safe ones about once in n + 1, so the forecast must not claim certainty there. Every bound's rule keeps
 * the raw-value clause (below the lowest safe training reading), so the run is warned where that one-line rule warns
 * it, and the warning says so rather than resting on the probability.
 */
class EdgeOfTrainingTest {

    @TempDir
    Path tmp;

    @Test
    void aSafeRunJustBelowEveryTrainingRunIsNotWarnedAsCertain() throws Exception {
        Path logs = SimulatedSets.write(tmp.resolve("train"), 12, 501);
        Path models = tmp.resolve("models");
        Cli learned = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString());
        assertEquals(0, learned.code(), learned.err());
        Path run = tmp.resolve("recharge-7034.log");
        Cli simulated = Cli.run("simulate", "--scenario", "recharge", "--seed", "7034", "--out", run.toString());
        assertEquals(0, simulated.code(), simulated.err());

        Cli watched = Cli.run("watch", "--no-follow", "--json", "--log", run.toString(), "--models",
                models.toString());
        assertTrue(watched.code() == 0 || watched.code() == 1,
                "a safe run is warned or quiet, never violated: " + watched.code() + " " + watched.err());
        int forecasts = 0;
        for (JsonNode e : watched.jsonLines()) {
            if (!e.path("property").asText().equals("battery")) {
                continue;
            }
            if (e.path("event").asText().equals("forecast")) {
                JsonNode p = e.path("forecast").path("probability");
                assertTrue(p.isNumber(), "a battery forecast without a probability: " + e);
                assertTrue(p.asDouble() < 0.99, "a battery forecast claims certainty on a run below every safe one: "
                        + e);
                forecasts++;
            }
            if (e.path("event").asText().equals("warning")) {
                assertEquals("novelty", e.path("clause").asText(),
                        "the warning is the raw-value clause's, not the probability's: " + e);
                assertTrue(e.path("reason").asText().contains("below the lowest"), e.toString());
            }
        }
        assertTrue(forecasts > 0, "the battery was forecast: " + watched.out());

        // The same models still warn a depleted run they never saw, before its violation.
        Path depleted = tmp.resolve("depleted-7001.log");
        assertEquals(0, Cli.run("simulate", "--scenario", "depleted", "--seed", "7001", "--out",
                depleted.toString()).code());
        Cli faulty = Cli.run("watch", "--no-follow", "--log", depleted.toString(), "--models", models.toString());
        assertEquals(1, faulty.code(), faulty.out() + faulty.err());
        String out = faulty.out();
        assertTrue(out.indexOf("WARNING") >= 0 && out.indexOf("WARNING") < out.indexOf("VIOLATION"), out);
    }
}
