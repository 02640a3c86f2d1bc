package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The forecast as a user meets it: learned with the models from the shipped sample logs, then on simulated runs none
 * of them saw: a forecast event, the forecast under warning and end, through a navigation that aborts (behaviour no
 * model has seen), and several runs of a log without ticks told apart.
 */
class ForecastCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    static Path tmp;
    static Path models;

    @BeforeAll
    static void learn() {
        models = tmp.resolve("models");
        Cli r = Cli.run("learn", "--logs", "sample-logs", "--models", models.toString());
        assertEquals(0, r.code(), r.err());
    }

    private static List<JsonNode> watch(Path log, String... more) throws Exception {
        List<String> args = new ArrayList<>(List.of("watch", "--no-follow", "--json", "--log", log.toString(),
                "--models", models.toString()));
        args.addAll(List.of(more));
        return Cli.run(args.toArray(String[]::new)).jsonLines();
    }

    private static Path simulate(String name, String... options) {
        Path log = tmp.resolve(name);
        List<String> args = new ArrayList<>(List.of("simulate", "--out", log.toString()));
        args.addAll(List.of(options));
        Cli r = Cli.run(args.toArray(String[]::new));
        assertEquals(0, r.code(), r.err());
        return log;
    }

    @Test
    void learnStoresTheForecastBesideTheMachinesAndListsIt() throws Exception {
        assertTrue(Files.isRegularFile(models.resolve("forecast.json")));
        JsonNode index = JSON.readTree(models.resolve("index.json").toFile());
        assertEquals("forecast.json", index.get("forecast").asText());
        JsonNode f = JSON.readTree(models.resolve("forecast.json").toFile());
        assertEquals(30, f.get("runs").asInt(), "every training run is counted");
        JsonNode battery = f.get("properties").get("battery");
        assertEquals(30, battery.get("runs").asInt());
        assertTrue(battery.get("thresholdValidated").asBoolean(), battery.get("thresholdNote").asText());
    }

    @Test
    void anUnseenDepletedRunHasForecastsAndAWarningThatSaysWhy() throws Exception {
        List<JsonNode> events = watch(simulate("depleted.log", "--scenario", "depleted", "--seed", "424242"));
        // the battery's forecasts; a bounded response's deadline forecasts carry "deadline" instead
        List<JsonNode> forecasts = events.stream().filter(e -> e.get("event").asText().equals("forecast")
                && !e.get("forecast").isNull()).toList();
        assertFalse(forecasts.isEmpty());
        for (JsonNode e : events) {
            if (e.get("event").asText().equals("forecast") && e.get("forecast").isNull()) {
                JsonNode d = e.get("deadline");
                assertTrue(d.get("novel").asBoolean() || (d.get("probability").asDouble() >= 0
                        && d.get("probability").asDouble() <= 1), e.toString());
            }
        }
        for (JsonNode e : forecasts) {
            double p = e.get("forecast").get("probability").asDouble();
            assertTrue(p >= 0 && p <= 1, e.toString());
            assertTrue(e.get("forecast").has("timeToViolation"), e.toString());
        }
        assertTrue(forecasts.size() < 60, "a forecast event when it changes, not one per pair: " + forecasts.size());
        JsonNode warning = events.stream().filter(e -> e.get("event").asText().equals("warning")).findFirst()
                .orElseThrow(() -> new AssertionError("no warning: " + events));
        assertEquals("forecast", warning.get("rule").asText());
        assertTrue(warning.get("reason").asText().contains("training runs"), warning.toString());
        assertNotNull(warning.get("forecast").get("timeToViolation").numberValue(), "falling battery: a time");
        JsonNode violation = events.stream().filter(e -> e.get("event").asText().equals("violation")).findFirst()
                .orElseThrow();
        assertTrue(warning.get("time").asDouble() < violation.get("time").asDouble(), "warned before the violation");
        JsonNode end = events.get(events.size() - 1);
        assertEquals("end", end.get("event").asText());
        assertTrue(end.get("forecast").isObject(), end.toString());
        assertTrue(end.get("runs").get(0).get("forecast").isObject());
    }

    @Test
    void explainPrintsTheForecastAfterEveryPairAndWhyWatchWarned() throws Exception {
        Path log = simulate("explained.log", "--scenario", "depleted", "--seed", "424242");
        Cli text = Cli.run("explain", "--log", log.toString(), "--models", models.toString());
        assertEquals(ExitCodes.WARNING, text.code(), text.err());
        List<String> lines = text.out().lines().toList();
        long pairs = lines.stream().filter(l -> l.matches("\\s+\\d+\\s+t=.*")).count();
        long forecasts = lines.stream().filter(l -> l.startsWith("        P(violation) ")).count();
        assertTrue(pairs > 5 && forecasts == pairs, "a forecast under each of the " + pairs + " pairs: " + text.out());
        String verdict = lines.stream().filter(l -> l.startsWith("watch WARNS of battery at")).findFirst()
                .orElseThrow(() -> new AssertionError(text.out()));
        assertTrue(verdict.contains("rule forecast: ") && verdict.contains("training runs"), verdict);

        Cli json = Cli.run("explain", "--json", "--log", log.toString(), "--models", models.toString());
        JsonNode x = JSON.readTree(json.out());
        assertEquals("forecast", x.get("rule").asText());
        assertTrue(x.get("warning").asText().contains("P(violation)"), x.get("warning").toString());
        for (JsonNode step : x.get("steps")) {
            double p = step.get("forecast").get("probability").asDouble();
            assertTrue(p >= 0 && p <= 1, step.toString());
        }
    }

    @Test
    void anAbortedNavigationIsNovelYetTheForecastGoesOnToTheEnd() throws Exception {
        List<JsonNode> events = watch(simulate("aborted.log", "--scenario", "depleted", "--seed", "31337", "--aborts",
                "1", "--abort-on", "station"));
        long noMatchLine = events.stream().filter(e -> e.get("event").asText().equals("no-match"))
                .mapToLong(e -> e.get("line").asLong()).findFirst().orElse(-1);
        assertTrue(noMatchLine > 0, "the abort is behaviour no model has seen: " + events);
        assertTrue(events.stream().anyMatch(e -> e.get("event").asText().equals("forecast")
                && e.get("line").asLong() >= noMatchLine), "forecasts go on after the no-match");
        JsonNode end = events.get(events.size() - 1);
        assertTrue(end.get("noMatch").asBoolean(), "the no-match is still reported");
        assertTrue(end.get("forecast").get("novelSince").isNumber(), end.toString());
        assertTrue(events.stream().anyMatch(e -> e.get("event").asText().equals("warning")), "still warned");
    }

    @Test
    void runsOfALogWithoutTicksFiveSecondsApartAreJudgedOneByOne() throws Exception {
        Path log = simulate("day.log", "--scenario", "direct,depleted,recharge", "--seed", "77", "--runs-per-log", "3",
                "--gap", "5", "--no-ticks");
        List<JsonNode> events = watch(log);
        JsonNode end = events.get(events.size() - 1);
        assertEquals(3, end.get("runs").size(), end.toString());
        assertTrue(end.get("runs").get(1).get("warning").asBoolean(), "the depleted run, second, is warned: " + end);
        assertFalse(end.get("runs").get(0).get("warning").asBoolean());
    }

    @Test
    void modelsLearnedBeforeForecastsStillLoadAndSaySo() throws Exception {
        Path old = tmp.resolve("old-models");
        Files.createDirectories(old);
        try (var files = Files.list(models)) {
            for (Path p : files.toList()) {
                if (!p.getFileName().toString().equals("forecast.json")) {
                    Files.copy(p, old.resolve(p.getFileName()));
                }
            }
        }
        ObjectNode index = (ObjectNode) JSON.readTree(old.resolve("index.json").toFile());
        index.remove("forecast");
        Files.writeString(old.resolve("index.json"), JSON.writeValueAsString(index));
        Path log = simulate("old.log", "--scenario", "depleted", "--seed", "5150");
        Cli r = Cli.run("watch", "--no-follow", "--log", log.toString(), "--models", old.toString());
        assertTrue(r.err().contains("learned without a forecast"), r.err());
        assertTrue(r.out().contains("every nominal model eliminated") || r.out().contains("no warning"), r.out());
        Cli asked = Cli.run("watch", "--no-follow", "--log", log.toString(), "--models", old.toString(), "--rule",
                "forecast");
        assertEquals(ExitCodes.USAGE, asked.code(), asked.err());
    }
}
