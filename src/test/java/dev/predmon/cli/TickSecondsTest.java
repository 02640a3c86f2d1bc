package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code watch --tick-seconds S} on logs without time stamps, counted in ticks: every time shown is in seconds, S per
 * tick, and nothing else changes.
 */
class TickSecondsTest {

    private static final SimOptions O = SimOptions.defaults();

    @TempDir
    Path dir;

    /** A simulated run as the monitor's console output: no time stamps, so counted in the tree's ticks. */
    private static String console(Scenario s, long seed) {
        return LogWriter.toText(Simulator.run(s, seed, O), O).replaceAll("(?m)^[0-9.]+\tDEBUG\t", "[DEBUG] ");
    }

    private static JsonNode first(List<JsonNode> events, String kind) {
        return Cli.firstEvent(events, kind).orElseThrow(() -> new AssertionError("no " + kind + " in " + events));
    }

    @Test
    void everyTimeOfALogCountedInTicksIsShownInSeconds() throws Exception {
        Path recordings = Files.createDirectories(dir.resolve("recordings"));
        for (long seed = 1; seed <= 3; seed++) {
            Files.writeString(recordings.resolve("d" + seed + ".txt"), console(Scenario.DEPLETED, seed));
            Files.writeString(recordings.resolve("r" + seed + ".txt"), console(Scenario.RECHARGE, seed));
        }
        Path models = dir.resolve("models");
        Cli learn = Cli.run("learn", "--logs", recordings.toString(), "--models", models.toString());
        assertEquals(ExitCodes.OK, learn.code(), learn.err());
        Path log = Files.writeString(dir.resolve("robot.txt"), console(Scenario.DEPLETED, 9001));

        Cli ticks = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow", "--json");
        Cli seconds = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow", "--json",
                "--tick-seconds", "0.5");
        assertEquals(ticks.code(), seconds.code(), seconds.err());
        List<JsonNode> inTicks = ticks.jsonLines();
        List<JsonNode> inSeconds = seconds.jsonLines();
        assertEquals(inTicks.size(), inSeconds.size(), "the same events");
        JsonNode violation = first(inTicks, "violation");
        assertEquals("ticks", violation.get("unit").asText());
        assertEquals("s", first(inSeconds, "violation").get("unit").asText());
        assertEquals(violation.get("time").asDouble() * 0.5, first(inSeconds, "violation").get("time").asDouble(),
                1e-9);
        assertEquals(violation.get("line").asLong(), first(inSeconds, "violation").get("line").asLong());

        JsonNode warning = first(inTicks, "warning");
        JsonNode warningS = first(inSeconds, "warning");
        assertEquals(warning.get("time").asDouble() * 0.5, warningS.get("time").asDouble(), 1e-9);
        JsonNode forecast = warning.get("forecast");
        JsonNode forecastS = warningS.get("forecast");
        assertEquals("ticks", forecast.get("unit").asText());
        assertEquals("s", forecastS.get("unit").asText());
        assertEquals(forecast.get("probability").asDouble(), forecastS.get("probability").asDouble());
        assertTrue(forecast.get("timeToViolation").isNumber(), forecast.toString());
        assertEquals(forecast.get("timeToViolation").asDouble() * 0.5, forecastS.get("timeToViolation").asDouble(),
                1e-3);
        assertEquals(forecast.get("drift").asDouble() / 0.5, forecastS.get("drift").asDouble(), 1e-3, "per second");
        assertTrue(warningS.get("reason").asText().contains(" s to the violation"), warningS.toString());
        assertTrue(warning.get("reason").asText().contains(" ticks to the violation"), warning.toString());
        JsonNode end = first(inTicks, "end");
        JsonNode endS = first(inSeconds, "end");
        assertEquals("s", endS.get("unit").asText());
        assertTrue(end.get("lead").isNumber(), end.toString());
        assertEquals(end.get("lead").asDouble() * 0.5, endS.get("lead").asDouble(), 1e-9);

        Cli tenths = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow", "--json",
                "--tick-seconds", "0.1");
        for (JsonNode e : tenths.jsonLines()) {
            if (e.has("time")) {
                assertTrue(e.get("time").asText().matches("\\d+(\\.\\d)?"), "tenths of a second, no binary tail: " + e);
            }
        }
        Cli text = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow",
                "--tick-seconds", "0.5");
        String violationLine = text.out().lines().filter(l -> l.contains("VIOLATION")).findFirst().orElseThrow();
        assertTrue(violationLine.startsWith("t="), violationLine);
        // every time is in seconds; a property's deadline in ticks counts the tree's ticks, in its own verdict line
        assertFalse(text.out().lines().filter(l -> !l.startsWith("  ")).anyMatch(l -> l.contains("tick")),
                "no tick left: " + text.out());
    }

    @Test
    void aTickLastsAPositiveTime() {
        // 1e308 s a tick would make every time Infinity, "time":"Infinity" in --json
        for (String bad : List.of("0", "-1", "Infinity", "1e308", "3601")) {
            Cli r = Cli.run("watch", "--log", "x.log", "--no-follow", "--tick-seconds", bad);
            assertEquals(ExitCodes.USAGE, r.code(), bad + ": " + r.err());
            assertTrue(r.err().contains("--tick-seconds must be a number of seconds above 0 and at most 3600"), r.err());
        }
    }
}
