package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.ForecastTraining;
import dev.predmon.learn.HeldOutFolds;
import dev.predmon.learn.HeldOutRun;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.Traces;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every bound property gets a value forecast of its own: learned from simulated runs with the thesis's abstraction
 * plus a reserve floor (battery at least 40, which recharge runs cross on their way to the charger and direct runs do
 * not) and a ceiling (at most 99.5, which recharging crosses), each is forecast, warned and summed up under its own id
 * in {@code watch}.
 */
class BoundForecastCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path tmp;

    private Path abstraction() throws Exception {
        return abstraction(tmp);
    }

    /** The thesis's abstraction with the reserve floor and the ceiling, as a file in {@code tmp}. */
    static Path abstraction(Path tmp) throws Exception {
        Cli shown = Cli.run("abstraction", "show", "thesis");
        assertEquals(0, shown.code(), shown.err());
        ObjectNode a = (ObjectNode) JSON.readTree(shown.out());
        a.put("name", "thesis-reserve");
        ArrayNode properties = (ArrayNode) a.get("properties");
        JsonNode value = properties.get(0).get("value");
        ObjectNode reserve = properties.addObject();
        reserve.put("id", "reserve").put("name", "battery reserve >= 40%").put("kind", "bound")
                .put("action", "cut the tour short").put("floor", 40.0).set("value", value.deepCopy());
        ObjectNode full = properties.addObject();
        full.put("id", "full").put("name", "battery <= 99.5%").put("kind", "bound").put("action", "stop charging")
                .put("ceiling", 99.5).set("value", value.deepCopy());
        Path file = tmp.resolve("reserve.json");
        Files.writeString(file, a.toPrettyString());
        return file;
    }

    private Path simulate(String scenario, String seed, String... more) {
        return simulate(tmp, scenario, seed, more);
    }

    /** A simulated log of {@code scenario} in {@code tmp}, or with {@code more} arguments where they say. */
    static Path simulate(Path tmp, String scenario, String seed, String... more) {
        Path out = tmp.resolve(scenario + "-" + seed + ".log");
        List<String> args = new ArrayList<>(List.of("simulate", "--scenario", scenario, "--seed", seed));
        if (more.length == 0) {
            args.addAll(List.of("--out", out.toString()));
        } else {
            args.addAll(List.of(more));
        }
        Cli r = Cli.run(args.toArray(String[]::new));
        assertEquals(0, r.code(), r.err());
        return out;
    }

    private static List<JsonNode> events(Cli r) throws Exception {
        List<JsonNode> events = new ArrayList<>();
        for (String line : r.out().lines().toList()) {
            events.add(JSON.readTree(line));
        }
        return events;
    }

    private static List<JsonNode> of(List<JsonNode> events, String event, String property) {
        return events.stream().filter(e -> e.path("event").asText().equals(event)
                && e.path("property").asText().equals(property)).toList();
    }

    private Path trainingLogs() {
        return trainingLogs(tmp);
    }

    /** Eight simulated runs of each scenario, a log each, in a scenario directory each, in {@code tmp}. */
    static Path trainingLogs(Path tmp) {
        Path logs = tmp.resolve("logs");
        for (String s : List.of("direct", "recharge", "depleted")) {
            simulate(tmp, s, "200", "--runs", "8", "--out-dir", logs.resolve(s).toString());
        }
        return logs;
    }

    @Test
    void evaluateScoresEachBoundsWarningsFromItsOwnForecast() throws Exception {
        Cli r = Cli.run("evaluate", "--logs", trainingLogs().toString(), "--abstraction", abstraction().toString(),
                "--folds", "3", "--quiet");
        assertEquals(0, r.code(), r.err());
        Matcher reserve = Pattern.compile("\nreserve +24 +0 +(\\d+) +(\\d+) +(\\d+) ").matcher(r.out());
        assertTrue(reserve.find(), r.out());
        int violated = Integer.parseInt(reserve.group(1));
        int warned = Integer.parseInt(reserve.group(2));
        assertTrue(violated > 8, "the depleted runs and the recharge runs that crossed 40: " + r.out());
        assertTrue(warned > violated / 2, "most warned ahead by the reserve's own forecast: " + r.out());
        Matcher full = Pattern.compile("\nfull +24 +0 +8 +(\\d+) ").matcher(r.out());
        assertTrue(full.find(), "every recharge run overcharges: " + r.out());
        assertTrue(Integer.parseInt(full.group(1)) > 0, r.out());
        // and each bound's value forecast is scored per run in the block of the other properties' forecasts
        Matcher reserveScore = scored("reserve").matcher(r.out());
        assertTrue(reserveScore.find(), r.out());
        assertEquals(violated, Integer.parseInt(reserveScore.group(1)), "the runs its table counts as violated");
        Matcher fullScore = scored("full").matcher(r.out());
        assertTrue(fullScore.find(), r.out());
        assertEquals(8, Integer.parseInt(fullScore.group(1)), r.out());
    }

    /** The line of {@code property}'s value forecast in evaluate's text: its runs, violated ones, Brier scores. */
    private static Pattern scored(String property) {
        return Pattern.compile("\n  " + property + ": per run, 24 runs with forecasts, \\d+ forecasts, (\\d+) "
                + "violated: Brier score \\d\\.\\d{3} \\(always saying the base rate: \\d\\.\\d{3}\\), expected "
                + "calibration error \\d\\.\\d{3} ");
    }

    /**
     * learn replays each held-out log once per fold for every property: the reserve's and the ceiling's held-out runs
     * are the battery's runs of the same replays, each as the property saw them (its own violation).
     */
    @Test
    void everyBoundIsJudgedOnTheSameHeldOutReplaysAsTheBattery() throws Exception {
        Abstraction abstraction = AbstractionFiles.load(abstraction());
        List<ScenarioSpec> specs = ScenarioLayout.scan(trainingLogs(), abstraction);
        Map<Path, LogTrace> traces = Traces.readAll(specs.stream().flatMap(s -> s.logs().stream()).toList(),
                abstraction);
        HeldOutFolds held = ForecastTraining.heldOut(specs, traces, MealyAlphabet.inputs(abstraction), abstraction,
                abstraction.confirm());
        assertEquals(5, held.folds());
        int runs = 0;
        int reserveViolated = 0;
        for (HeldOutFolds.Fold fold : held.judged()) {
            assertEquals(Set.of("reserve", "full"), fold.bounds().keySet(), "fold " + fold.index());
            for (HeldOutFolds.BoundFold b : fold.bounds().values()) {
                assertEquals(fold.runs().size(), b.runs().size(), "the same held-out runs, fold " + fold.index());
                assertTrue(b.baseRate() > 0 && b.baseRate() < 1, "trained on both outcomes: " + b.baseRate());
            }
            runs += fold.runs().size();
            reserveViolated += (int) fold.bounds().get("reserve").runs().stream().filter(HeldOutRun::violated).count();
        }
        assertEquals(24, runs, "every training run held out once");
        long inLogs = traces.values().stream().flatMap(t -> t.runs().stream())
                .filter(r -> r.timing().violated("reserve")).count();
        assertEquals(inLogs, reserveViolated, "labelled by the reserve's own violation");
        assertTrue(reserveViolated > 8, "recharge runs cross the reserve and keep the battery's floor");
    }

    @Test
    void aReserveFloorAndACeilingAreForecastAndWarnedEachUnderItsOwnId() throws Exception {
        Path abstraction = abstraction();
        Path logs = trainingLogs();
        Path models = tmp.resolve("models");
        Cli learn = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString(), "--abstraction",
                abstraction.toString());
        assertEquals(0, learn.code(), learn.err());
        assertTrue(learn.out().contains("scorecard of 'battery reserve >= 40%' (5-fold cross-validation on 24 runs)"),
                learn.out());
        assertTrue(learn.out().contains("scorecard of 'battery <= 99.5%' (5-fold"), learn.out());
        JsonNode all = JSON.readTree(models.resolve("forecast.json").toFile()).get("properties");
        JsonNode forecast = all.get("battery");
        assertEquals("floor", forecast.get("side").asText(), "the battery's forecast is a bound's as any other");
        assertEquals(20.0, forecast.get("limit").asDouble());
        JsonNode reserve = all.get("reserve");
        assertEquals("floor", reserve.get("side").asText());
        assertEquals(40.0, reserve.get("limit").asDouble());
        assertTrue(reserve.get("violating").asInt() > forecast.get("violating").asInt(),
                "labelled by its own violation: recharge runs cross 40 and hold 20 " + reserve);
        assertTrue(reserve.get("thresholdValidated").asBoolean(), reserve.toString());
        JsonNode full = all.get("full");
        assertEquals("ceiling", full.get("side").asText());
        assertEquals(-99.5, full.get("limit").asDouble(), "a ceiling is forecast as the floor of the mirrored value");

        // a recharge run crosses the reserve: warned before it, as its own property with its own action
        Path recharge = simulate("recharge", "500");
        Cli watched = Cli.run("watch", "--log", recharge.toString(), "--models", models.toString(), "--no-follow",
                "--json");
        List<JsonNode> events = events(watched);
        List<JsonNode> violations = of(events, "violation", "reserve");
        assertEquals(1, violations.size(), watched.out());
        long violatedAt = violations.get(0).get("line").asLong();
        List<JsonNode> warnings = of(events, "warning", "reserve");
        assertFalse(warnings.isEmpty(), watched.out());
        JsonNode warning = warnings.get(0);
        assertTrue(warning.get("line").asLong() < violatedAt, warning + " before line " + violatedAt);
        assertTrue(warning.get("reason").asText().startsWith("'battery reserve >= 40%' (reserve): P(violation) "),
                warning.toString());
        assertTrue(warning.get("reason").asText().endsWith("; do now: cut the tour short"), warning.toString());
        assertTrue(warning.get("forecast").get("probability").asDouble() > 0, warning.toString());
        List<JsonNode> forecasts = of(events, "forecast", "reserve");
        assertTrue(forecasts.stream().anyMatch(f -> f.get("line").asLong() < violatedAt), watched.out());
        assertTrue(forecasts.stream().allMatch(f -> f.get("forecast").get("value").isNull()
                || f.get("forecast").get("value").asDouble() >= 0), "values as the property reads them");
        assertFalse(of(events, "forecast", "full").isEmpty(), "the ceiling is forecast too");
        assertTrue(of(events, "warning", "full").get(0).get("line").asLong()
                < of(events, "violation", "full").get(0).get("line").asLong(), "and warned before its violation");
        JsonNode end = events.get(events.size() - 1);
        assertEquals("end", end.get("event").asText());
        assertFalse(end.get("violation").asBoolean(), "the run's violation is still the battery's: " + end);
        assertFalse(end.get("warning").asBoolean(), "and so is its warning: " + end);
        JsonNode props = end.get("properties");
        JsonNode reserveEnd = props.get(5);
        assertEquals("reserve", reserveEnd.get("property").asText());
        assertEquals("violated", reserveEnd.get("verdict").asText());
        assertEquals("forecast", reserveEnd.get("forecast").get("model").asText());
        assertTrue(reserveEnd.get("forecast").get("probability").isNumber(), reserveEnd.toString());
        assertEquals("forecast", props.get(6).get("forecast").get("model").asText());

        Cli text = Cli.run("watch", "--log", recharge.toString(), "--models", models.toString(), "--no-follow");
        assertTrue(text.out().contains(": WARNING: 'battery reserve >= 40%' (reserve): P(violation) "), text.out());
        assertTrue(text.out().contains("\n  reserve (battery reserve >= 40%): violated at line " + violatedAt),
                text.out());

        // a direct run keeps its reserve: forecast, never warned
        Path direct = simulate("direct", "501");
        List<JsonNode> held = events(Cli.run("watch", "--log", direct.toString(), "--models", models.toString(),
                "--no-follow", "--json"));
        assertFalse(of(held, "forecast", "reserve").isEmpty());
        assertTrue(of(held, "warning", "reserve").isEmpty(), held.toString());
        assertTrue(of(held, "violation", "reserve").isEmpty(), held.toString());
        assertTrue(of(held, "warning", "full").isEmpty(), held.toString());
    }
}
