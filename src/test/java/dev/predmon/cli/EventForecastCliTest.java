package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * An absence gets a forecast like a bound: on simulated runs whose way to the charging station is blocked (every
 * recharge run of training aborts there, {@code --aborts 1 --abort-on station}), the forecast of "navigation never
 * aborts" learns that heading for the charger leads to an abort, and warns of it before it comes in runs it never saw,
 * where always saying the base rate (9 of 19 training runs violated it: under even odds) warns none. An absence that
 * no training run violated ("no getStatus reply 4") says it has no forecast, and why.
 */
class EventForecastCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    static Path tmp;
    static Path abstraction;
    static Path train;
    static Path test;

    @BeforeAll
    static void simulate() throws Exception {
        train = tmp.resolve("train");
        test = tmp.resolve("test");
        simulate(train, "direct", "100", "10");
        simulate(train, "recharge", "1100", "5", "--aborts", "1", "--abort-on", "station");
        simulate(train, "depleted", "2100", "4");
        simulate(test, "direct", "5000", "5");
        simulate(test, "recharge", "6000", "5", "--aborts", "1", "--abort-on", "station");
        simulate(test, "recharge", "6100", "3");
        Cli shown = Cli.run("abstraction", "show", "thesis");
        assertEquals(0, shown.code(), shown.err());
        ObjectNode a = (ObjectNode) JSON.readTree(shown.out());
        a.put("name", "thesis-no-fail");
        ObjectNode noFail = ((ArrayNode) a.get("properties")).addObject();
        noFail.put("id", "no-fail").put("name", "navigation never fails").put("kind", "absence");
        noFail.putObject("event").put("kind", "reply").put("protocol", "GoTo").put("command", "getStatus")
                .put("reply", "4");
        abstraction = tmp.resolve("no-fail.json");
        Files.writeString(abstraction, a.toPrettyString());
    }

    private static void simulate(Path dir, String scenario, String seed, String runs, String... more) {
        List<String> args = new ArrayList<>(List.of("simulate", "--scenario", scenario, "--seed", seed, "--runs", runs,
                "--out-dir", dir.resolve(scenario).toString()));
        args.addAll(List.of(more));
        Cli r = Cli.run(args.toArray(String[]::new));
        assertEquals(0, r.code(), r.err());
    }

    @Test
    void watchAndExplainForecastTheAbortAndSayWhyTheOtherAbsenceHasNone() throws Exception {
        Path models = tmp.resolve("models");
        Cli learned = Cli.run("learn", "--logs", train.toString(), "--models", models.toString(), "--abstraction",
                abstraction.toString());
        assertEquals(0, learned.code(), learned.err());
        assertTrue(learned.out().contains("no-abort: violated in 9 of 19 runs"), learned.out());
        Matcher card = Pattern.compile("scorecard of 'navigation never aborts' \\(5-fold cross-validation on 19 "
                + "runs\\): warned (\\d+) of 9 violations.*\n.*\n  baseline on the same folds, base rate: warn every "
                + "run if the training runs violated it at even odds or more, else none: warned (\\d+) of 9, .*; the "
                + "forecast's rule warns").matcher(learned.out());
        assertTrue(card.find(), learned.out());
        assertTrue(Integer.parseInt(card.group(1)) > Integer.parseInt(card.group(2)),
                "on the held-out folds the forecast warned more aborts ahead than the base rate: " + card.group());
        assertTrue(learned.out().contains("no-fail: no forecast: never violated in 19 training runs"), learned.out());

        Path log = test.resolve("recharge/recharge-6000.log");
        Cli watched = Cli.run("watch", "--models", models.toString(), "--json", "--no-follow", "--log", log.toString());
        List<JsonNode> events = new ArrayList<>();
        for (String line : watched.out().lines().toList()) {
            events.add(JSON.readTree(line));
        }
        List<JsonNode> forecasts = of(events, "forecast", "no-abort");
        assertFalse(forecasts.isEmpty(), watched.out());
        assertTrue(forecasts.get(0).path("forecast").path("value").isNull(), "an event has no value");
        List<JsonNode> warnings = of(events, "warning", "no-abort");
        List<JsonNode> violations = of(events, "violation", "no-abort");
        assertEquals(1, violations.size(), watched.out());
        assertEquals(1, warnings.size(), watched.out());
        assertTrue(warnings.get(0).path("line").asLong() < violations.get(0).path("line").asLong(),
                "warned before the abort: " + warnings.get(0));
        assertTrue(warnings.get(0).path("reason").asText().contains("that GoTo/getStatus reply 3 comes in the rest "
                + "of the run, reaching the warning threshold"), warnings.get(0).toString());
        JsonNode end = events.get(events.size() - 1);
        assertEquals("end", end.path("event").asText());
        assertEquals("no forecast: never violated in 19 training runs", property(end, "no-fail").path("forecast")
                .path("words").asText(), end.toString());
        assertEquals(1, watched.code(), "a warning, then its violation: " + watched.err());

        Cli explained = Cli.run("explain", "--models", models.toString(), "--log", log.toString());
        assertTrue(explained.out().contains("watch WARNS of no-abort"), explained.out());
        assertTrue(Pattern.compile("\nno-abort's forecast: P\\(violation\\) peaked at \\d\\.\\d\\d over \\d+ "
                + "forecast\\(s\\) before its violation at t=").matcher(explained.out()).find(), explained.out());
        assertTrue(explained.out().contains("\nno-fail: no forecast: never violated in 19 training runs"),
                explained.out());
    }

    @Test
    void onRunsItNeverSawTheForecastWarnsAbortsTheBaseRateDoesNot() {
        Cli r = Cli.run("evaluate", "--logs", train.toString(), "--test", test.toString(), "--abstraction",
                abstraction.toString(), "--quiet");
        assertEquals(0, r.code(), r.err());
        Matcher row = Pattern.compile("\nno-abort +13 +0 +5 +(\\d+) +(\\d+) +\\S+ +(\\d+) +(\\d+) ").matcher(r.out());
        assertTrue(row.find(), r.out());
        int warned = Integer.parseInt(row.group(1));
        int alarms = Integer.parseInt(row.group(2));
        assertTrue(warned >= 4, "the aborts on the way to the charger warned ahead: " + row.group());
        assertEquals(0, Integer.parseInt(row.group(3)), "the base rate (under even odds) warns no run");
        assertEquals(0, Integer.parseInt(row.group(4)));
        assertTrue(alarms <= 3, "only the 3 recharge runs whose way was clear can be false alarms: " + row.group());
        assertTrue(Pattern.compile("\n  no-abort: per run, 13 runs with forecasts, \\d+ forecasts, 5 violated: Brier "
                + "score \\d\\.\\d{3} \\(always saying the base rate: \\d\\.\\d{3}\\)").matcher(r.out()).find(),
                r.out());
        assertTrue(r.out().contains("\n  no-fail: no forecast: never violated in 19 training runs"), r.out());
    }

    private static List<JsonNode> of(List<JsonNode> events, String event, String property) {
        return events.stream().filter(e -> e.path("event").asText().equals(event)
                && e.path("property").asText().equals(property)).toList();
    }

    private static JsonNode property(JsonNode end, String id) {
        for (JsonNode p : end.path("properties")) {
            if (p.path("property").asText().equals(id)) {
                return p;
            }
        }
        throw new AssertionError("no property " + id + " in " + end);
    }
}
