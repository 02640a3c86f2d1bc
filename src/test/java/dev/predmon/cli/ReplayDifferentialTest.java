package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.evaluate.Replay;
import dev.predmon.evaluate.RunResult;
import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.forecast.Survival;
import dev.predmon.learn.DeadlineTraining;
import dev.predmon.learn.HeldOutFolds;
import dev.predmon.learn.HeldOutRun;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.WarningRule;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.property.Property;
import dev.predmon.property.Response;
import dev.predmon.replay.LogReplay;
import dev.predmon.replay.ReplayedLog;
import dev.predmon.replay.ReplayedRun;
import dev.predmon.support.RealLogs;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every path that judges a log judges it alike: {@code learn}'s held-out replay ({@link HeldOutRun#replayAll}, which
 * chooses the threshold and the calibration), {@code evaluate}'s {@link Replay}, {@code explain}, {@code classify} and
 * {@code watch --no-follow --json}, each run in process, against the one replay of the log ({@link LogReplay}). Per
 * run they must give the same forecasts (probability and time to the violation, as numbers: exactly where a path
 * hands doubles over, to the printed four decimals where it prints them), the same warnings (line, clause, property,
 * probability), the same verdict of every property and the same exit code. Watch prints only the forecasts that
 * changed: those must be, in order, a subsequence of the replay's every forecast.
 */
class ReplayDifferentialTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path tmp;

    @Test
    void everySampleLogWithTheShippedModels() throws Exception {
        List<Path> logs = files(Path.of("sample-logs"), ".log");
        assertEquals(30, logs.size());
        Paths paths = new Paths(Path.of("models"));
        assertEquals(List.of(), disagreements(logs, paths));
        assertTrue(paths.forecasts > 500, "forecasts compared: " + paths.forecasts);
        assertTrue(paths.warnings > 5, "warnings compared: " + paths.warnings);
        assertTrue(paths.deadlines >= 30, "deadline forecasts compared: " + paths.deadlines);
    }

    @Test
    void everySimulatedNovelty() throws Exception {
        List<List<String>> novelties = List.of(List.of("--aborts", "1"), List.of("--never-arrives", "450"),
                List.of("--grasp", "--grasp-failures", "12"), List.of("--late-turn", "15"), List.of("--noise", "0.5"),
                List.of("--new-location", "garden"), List.of("--no-ticks"), List.of("--slowdown", "1.5"),
                List.of("--drain-factor", "1.3"), List.of("--runs", "3"), List.of("--tick-period", "0.5"),
                List.of("--stuck", "20", "--aborts", "1"), List.of("--late-replies", "0.3"),
                List.of("--abort-on", "station", "--aborts", "2"), List.of("--gap", "3", "--runs", "2"),
                List.of("--no-ticks", "--runs", "2", "--noise", "0.3"));
        List<String> scenarios = List.of("direct", "recharge", "depleted");
        List<Path> logs = new ArrayList<>();
        for (int n = 0; n < novelties.size(); n++) {
            String scenario = scenarios.get(n % scenarios.size());
            Path log = tmp.resolve("n" + n + "-" + scenario + ".log");
            List<String> args = new ArrayList<>(List.of("simulate", "--scenario", scenario, "--seed",
                    Integer.toString(900 + n), "--out", log.toString()));
            args.addAll(novelties.get(n));
            Cli r = Cli.run(args.toArray(String[]::new));
            assertEquals(0, r.code(), novelties.get(n) + " " + scenario + ": " + r.err());
            logs.add(log);
        }
        // A noisy run sent to a new place: the known case where learn's offline forecasts once differed from watch's.
        Path noisy = tmp.resolve("noisy-new-place.log");
        Cli r = Cli.run("simulate", "--scenario", "recharge", "--seed", "3", "--noise", "0.5", "--new-location",
                "office", "--out", noisy.toString());
        assertEquals(0, r.code(), r.err());
        logs.add(noisy);
        Paths paths = new Paths(Path.of("models"));
        assertEquals(List.of(), disagreements(logs, paths));
        assertTrue(paths.forecasts > 200, "forecasts compared: " + paths.forecasts);
        assertTrue(paths.deadlines >= 20, "deadline forecasts compared: " + paths.deadlines);
        assertTrue(paths.deadlineWarnings >= 1 && paths.letGo >= 1, "the navigation that never arrives: warned "
                + paths.deadlineWarnings + ", let go " + paths.letGo);
    }

    @Test
    void theRealRecordingsWithModelsLearnedOnThem() throws Exception {
        Assumptions.assumeTrue(Files.isDirectory(RealLogs.DIR), "skipped: no real recordings at "
                + RealLogs.DIR.toAbsolutePath().normalize() + " (they are not part of this repository)");
        Path models = tmp.resolve("real-models");
        Cli learned = Cli.run("learn", "--logs", RealLogs.DIR.toString(), "--abstraction", "scope-fetch", "--models",
                models.toString());
        assertEquals(0, learned.code(), learned.err());
        List<Path> logs = files(RealLogs.DIR, ".txt");
        assertTrue(logs.size() >= 40, "the 43 recordings: " + logs.size());
        Paths paths = new Paths(models);
        assertEquals(List.of(), disagreements(logs, paths));
        assertTrue(paths.forecasts > 1000, "forecasts compared: " + paths.forecasts);
        assertTrue(paths.deadlines >= 100, "deadline forecasts compared: " + paths.deadlines);
    }

    /**
     * Models learned on the sample logs, whose cross-validation chose the raw-value baseline for the battery: every
     * path warns by it alike (the clause of each warning included).
     */
    @Test
    void modelsWhoseBaselineWasChosenWarnAlikeOnEveryPath() throws Exception {
        Path models = tmp.resolve("baseline-models");
        Cli learned = Cli.run("learn", "--logs", "sample-logs", "--models", models.toString());
        assertEquals(0, learned.code(), learned.err());
        Paths paths = new Paths(models);
        assertTrue(paths.models.forecast().clauses().baseline(), "the raw value wins on these folds");
        List<Path> logs = List.of(Path.of("sample-logs/depleted/depleted-1.log"),
                Path.of("sample-logs/recharge/recharge-3.log"), BoundForecastCliTest.simulate(tmp, "depleted", "700",
                        "--new-location", "office", "--out", tmp.resolve("depleted-700.log").toString()),
                BoundForecastCliTest.simulate(tmp, "recharge", "701", "--aborts", "1", "--out",
                        tmp.resolve("recharge-701.log").toString()));
        assertEquals(List.of(), disagreements(logs, paths));
        assertTrue(paths.warnings >= 2, "warnings compared: " + paths.warnings);
    }

    /** Models that forecast two more bound properties, a reserve floor and a ceiling, each its own forecasts. */
    @Test
    void aReserveFloorAndACeilingForecastAlikeOnEveryPath() throws Exception {
        Path models = tmp.resolve("bound-models");
        Cli learned = Cli.run("learn", "--logs", BoundForecastCliTest.trainingLogs(tmp).toString(), "--models",
                models.toString(), "--abstraction", BoundForecastCliTest.abstraction(tmp).toString());
        assertEquals(0, learned.code(), learned.err());
        List<Path> logs = List.of(BoundForecastCliTest.simulate(tmp, "recharge", "500"),
                BoundForecastCliTest.simulate(tmp, "direct", "501"),
                BoundForecastCliTest.simulate(tmp, "depleted", "502"),
                BoundForecastCliTest.simulate(tmp, "recharge", "503", "--runs", "2", "--noise", "0.3", "--out",
                        tmp.resolve("recharge-503.log").toString()));
        Paths paths = new Paths(models);
        assertEquals(2, paths.models.forecast().bounds().size());
        assertEquals(List.of(), disagreements(logs, paths));
        assertTrue(paths.boundForecasts > 200, "bound forecasts compared: " + paths.boundForecasts);
        assertTrue(paths.warnings > 3, "warnings compared: " + paths.warnings);
    }

    /**
     * An absence with a forecast, the same absence scoped (from a goTo to the charging station until a goTo to the
     * kitchen), and a precedence with a forecast ("no abort before the first arrival"), learned from runs whose way to
     * the charger is blocked but in two: every path gives each the same forecasts, warnings, violations and verdicts.
     */
    @Test
    void anAbsenceAScopedAbsenceAndAPrecedenceForecastAlikeOnEveryPath() throws Exception {
        ObjectNode a = (ObjectNode) JSON.readTree(Cli.run("abstraction", "show", "thesis").out());
        a.put("name", "thesis-events");
        ArrayNode properties = (ArrayNode) a.get("properties");
        ObjectNode abort = JSON.createObjectNode().put("kind", "reply").put("protocol", "GoTo")
                .put("command", "getStatus").put("reply", "3");
        ObjectNode scoped = properties.addObject().put("id", "no-abort-to-charger")
                .put("name", "no abort on the way to the charger").put("kind", "absence");
        scoped.set("event", abort.deepCopy());
        ObjectNode scope = scoped.putObject("scope");
        scope.putObject("from").put("kind", "command").put("protocol", "GoTo").put("command", "goTo")
                .put("argument", "charging_station");
        scope.putObject("until").put("kind", "command").put("protocol", "GoTo").put("command", "goTo")
                .put("argument", "kitchen");
        ObjectNode first = properties.addObject().put("id", "arrive-first").put("name", "no abort before an arrival")
                .put("kind", "precedence");
        first.putObject("first").put("kind", "reply").put("protocol", "GoTo").put("command", "getStatus")
                .put("reply", "2");
        first.set("then", abort.deepCopy());
        Path abstraction = tmp.resolve("events.json");
        Files.writeString(abstraction, a.toPrettyString());
        Path logs = tmp.resolve("event-logs");
        BoundForecastCliTest.simulate(tmp, "direct", "100", "--runs", "6", "--out-dir", logs.resolve("direct").toString());
        BoundForecastCliTest.simulate(tmp, "recharge", "1100", "--runs", "5", "--aborts", "1", "--abort-on",
                "station", "--out-dir", logs.resolve("recharge").toString());
        BoundForecastCliTest.simulate(tmp, "recharge", "1200", "--runs", "2", "--out-dir",
                logs.resolve("recharge").toString());
        BoundForecastCliTest.simulate(tmp, "depleted", "2100", "--runs", "3", "--out-dir",
                logs.resolve("depleted").toString());
        Path models = tmp.resolve("event-models");
        Cli learned = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString(), "--abstraction",
                abstraction.toString());
        assertEquals(0, learned.code(), learned.err());
        List<Path> logsJudged = List.of(BoundForecastCliTest.simulate(tmp, "recharge", "6000", "--aborts", "1",
                        "--abort-on", "station", "--out", tmp.resolve("recharge-6000.log").toString()),
                BoundForecastCliTest.simulate(tmp, "direct", "5000"),
                BoundForecastCliTest.simulate(tmp, "recharge", "6100", "--runs", "2", "--aborts", "1", "--out",
                        tmp.resolve("recharge-6100.log").toString()));
        Paths paths = new Paths(models);
        assertEquals(List.of("arrive-first", "no-abort", "no-abort-to-charger"), own(paths).stream().sorted().toList(),
                learned.out());
        assertEquals(List.of(), disagreements(logsJudged, paths));
        assertTrue(paths.boundForecasts > 30, "event forecasts compared: " + paths.boundForecasts);
        assertTrue(paths.warnings > 2, "warnings compared: " + paths.warnings);
    }

    /**
     * Kinds by scope: the first floor scoped (the battery, from a goTo to the charging station until a goTo to the
     * kitchen), a reserve floor scoped the other way, the ceiling and the navigation deadline over the whole run. Every
     * path gives each the same forecasts, warnings, violations and verdicts; the unscoped kinds are the case above.
     */
    @Test
    void aScopedFirstFloorAScopedFloorACeilingAndADeadlineAlikeOnEveryPath() throws Exception {
        ObjectNode a = (ObjectNode) JSON.readTree(Files.readString(BoundForecastCliTest.abstraction(tmp)));
        a.put("name", "thesis-scoped-kinds");
        ArrayNode properties = (ArrayNode) a.get("properties");
        // the battery on the way to the charger (where the depleted runs violate it), the reserve to the kitchen
        String[][] scopes = {{"charging_station", "kitchen"}, {"kitchen", "charging_station"}};
        int[] scoped = {0, properties.size() - 2};
        for (int i = 0; i < scoped.length; i++) {
            ObjectNode scope = ((ObjectNode) properties.get(scoped[i])).putObject("scope");
            scope.putObject("from").put("kind", "command").put("protocol", "GoTo").put("command", "goTo")
                    .put("argument", scopes[i][0]);
            scope.putObject("until").put("kind", "command").put("protocol", "GoTo").put("command", "goTo")
                    .put("argument", scopes[i][1]);
        }
        List<String> kinds = new ArrayList<>();
        properties.forEach(p -> kinds.add(p.get("id").asText() + (p.has("scope") ? " scoped" : "")));
        assertTrue(kinds.containsAll(List.of("battery scoped", "reserve scoped", "full", "navigation-in-time")),
                kinds.toString());
        Path abstraction = tmp.resolve("scoped-kinds.json");
        Files.writeString(abstraction, a.toPrettyString());
        Path models = tmp.resolve("scoped-models");
        Cli learned = Cli.run("learn", "--logs", BoundForecastCliTest.trainingLogs(tmp).toString(), "--models",
                models.toString(), "--abstraction", abstraction.toString());
        assertEquals(0, learned.code(), learned.err());
        List<Path> logs = List.of(BoundForecastCliTest.simulate(tmp, "recharge", "600"),
                BoundForecastCliTest.simulate(tmp, "depleted", "601"),
                BoundForecastCliTest.simulate(tmp, "depleted", "602", "--runs", "2", "--noise", "0.3", "--out",
                        tmp.resolve("depleted-602.log").toString()),
                Path.of("sample-logs/depleted/depleted-1.log"));
        Paths paths = new Paths(models);
        assertEquals(WarningRule.FORECAST, paths.rule, "the scoped battery's forecast was validated");
        assertEquals(List.of(), disagreements(logs, paths));
        assertTrue(paths.forecasts > 100, "first-floor forecasts compared: " + paths.forecasts);
        assertTrue(paths.boundForecasts > 100, "bound forecasts compared: " + paths.boundForecasts);
        assertTrue(paths.deadlines > 0, "deadline forecasts compared: " + paths.deadlines);
    }

    /** The comparison is not blind: one forecast nudged by the last bit of its double is a disagreement. */
    @Test
    void aForecastOffByOneUlpIsADisagreement() throws Exception {
        Path log = Path.of("sample-logs/recharge/recharge-3.log");
        Paths paths = new Paths(Path.of("models"));
        ReplayedLog reference = paths.reference(log);
        List<Double> replayed = reference.runs().get(0).beforeViolation().stream()
                .map(t -> t.forecast().probability()).toList();
        List<Double> nudged = new ArrayList<>(replayed);
        nudged.set(nudged.size() / 2, Math.nextUp(nudged.get(nudged.size() / 2)));
        List<String> differ = new ArrayList<>();
        same(differ, "learn", log + " run 0 probabilities", replayed, nudged);
        assertEquals(1, differ.size(), differ.toString());
        assertTrue(differ.get(0).contains("item " + nudged.size() / 2), differ.get(0));
        List<String> none = new ArrayList<>();
        same(none, "learn", log + " run 0 probabilities", replayed, List.copyOf(replayed));
        assertEquals(List.of(), none);
    }

    /** Nor is the deadlines': one of learn's deadline forecasts nudged by the last bit of its double disagrees. */
    @Test
    void aDeadlineForecastOffByOneUlpIsADisagreement() throws Exception {
        Path log = Path.of("sample-logs/recharge/recharge-3.log");
        Paths paths = new Paths(Path.of("models"));
        HeldOutRun run = HeldOutRun.replayAll(log, RunLabel.ALL, paths.models, paths.abstraction, paths.confirm,
                paths.rule).safety().get(0);
        String id = "navigation-in-time";
        DeadlineRule rule = paths.models.forecast().deadlineRule(id);
        Response navigation = (Response) paths.abstraction.properties().stream().filter(p -> p.id().equals(id))
                .findFirst().orElseThrow();
        List<String> learned = Learned.of(run, navigation, paths.models.forecast()).forecasts();
        assertTrue(learned.size() > 10, "deadline forecasts: " + learned);
        List<ReplayedRun.Obligation> mine = run.obligations().stream().filter(o -> o.property().id().equals(id))
                .toList();
        List<String> told = new ArrayList<>();
        for (ReplayedRun.Obligation o : mine) {
            for (ReplayedRun.Step s : o.forecasts()) {
                Survival.Estimate e = rule.calibrated(s.estimate());
                told.add(deadline(s.line(), e.novel() ? null : e.probability(), e.timeLeft()));
            }
        }
        List<String> none = new ArrayList<>();
        subsequence(none, id, learned, told);
        assertEquals(List.of(), none);
        ReplayedRun.Step middle = mine.get(0).forecasts().get(1);
        Survival.Estimate e = rule.calibrated(middle.estimate());
        told.set(1, deadline(middle.line(), Math.nextUp(e.probability()), e.timeLeft()));
        List<String> differ = new ArrayList<>();
        subsequence(differ, id, learned, told);
        assertEquals(1, differ.size(), differ.toString());
        assertTrue(differ.get(0).contains(middle.line() + " "), differ.get(0));
    }

    /** The models of one directory, as every command loads them, and counts of what was compared. */
    private static final class Paths {
        final Path dir;
        final Abstraction abstraction;
        final ModelSet models;
        final int confirm;
        final WarningRule rule;
        int forecasts;
        int warnings;
        int boundForecasts;
        /** Deadline forecasts of learn's held-out obligations that watch told and that were compared. */
        int deadlines;
        /** Deadline warnings and obligations let go past their deadline or scope that learn's held-out replay has. */
        int deadlineWarnings;
        int letGo;

        Paths(Path dir) throws Exception {
            this.dir = dir;
            Abstraction stored = AbstractionFiles.load(ModelStore.storedAbstraction(dir).orElseThrow());
            this.models = ModelStore.read(dir, stored);
            this.abstraction = models.tune(stored);
            this.confirm = abstraction.confirm();
            this.rule = PredictiveMonitor.defaultRule(models);
        }

        ReplayedLog reference(Path log) throws IOException {
            return LogReplay.replay(log, models, abstraction, 0, confirm, rule, (r, run, judged) -> { });
        }
    }

    private static List<String> disagreements(List<Path> logs, Paths paths) throws Exception {
        List<String> differ = new ArrayList<>();
        for (Path log : logs) {
            ReplayedLog reference = paths.reference(log);
            int code = ExitCodes.ofMonitor(reference.monitor());
            for (ReplayedRun run : reference.runs()) {
                paths.forecasts += run.forecasts().size();
                paths.warnings += run.warnings().size();
            }
            watch(differ, log, paths, reference, code);
            evaluate(differ, log, paths, reference);
            learn(differ, log, paths, reference);
            explain(differ, log, paths, reference, code);
            classify(differ, log, paths, reference, code);
        }
        return differ;
    }

    /** {@code watch --no-follow --json}: the forecasts it prints, its warnings, its verdicts and its exit code. */
    private static void watch(List<String> differ, Path log, Paths paths, ReplayedLog reference, int code)
            throws IOException {
        Cli w = Cli.run("watch", "--no-follow", "--json", "--log", log.toString(), "--models", paths.dir.toString());
        same(differ, "watch", log + " exit code", code, w.code());
        List<JsonNode> events = w.jsonLines();
        String forecastId = paths.abstraction.safety().map(b -> b.id()).orElse(null);
        for (ReplayedRun run : reference.runs()) {
            String where = log + " run " + run.run();
            // the forecast property's, then each other bound's own (a deadline's are compared as warnings)
            told(differ, where, forecastId, run.forecasts(), run, events);
            for (String id : own(paths)) {
                paths.boundForecasts += run.boundForecasts().getOrDefault(id, List.of()).size();
                told(differ, where + " " + id, id, run.boundForecasts().getOrDefault(id, List.of()), run, events);
            }
            same(differ, "watch", where + " warnings (line, clause, property, probability)",
                    run.warnings().stream().map(x -> warning(x.line(), x.clause().id(), x.property(),
                            x.forecast() == null ? null : round(x.forecast().probability()))).toList(),
                    ofRun(events, "warning", run.run()).stream().map(e -> warning(e.get("line").asLong(),
                            e.get("clause").asText(), text(e.get("property")), e.get("forecast").isNull() ? null
                                    : e.get("forecast").get("probability").asDouble())).toList());
            same(differ, "watch", where + " violations (line, property)",
                    run.events().stream().filter(MonitorEvent.Violation.class::isInstance)
                            .map(MonitorEvent.Violation.class::cast).map(v -> v.line() + " " + v.property()).toList(),
                    ofRun(events, "violation", run.run()).stream().map(e -> e.get("line").asLong() + " "
                            + e.get("property").asText()).toList());
        }
        deadlines(differ, log, paths, reference, events);
        JsonNode end = events.get(events.size() - 1);
        if (!end.get("event").asText().equals("end")) {
            differ.add("watch: " + log + " ends with no end event");
            return;
        }
        List<String> verdicts = new ArrayList<>();
        end.get("runs").forEach(r -> r.get("properties").forEach(p -> verdicts.add(r.get("run").asInt() + " "
                + p.get("property").asText() + " " + p.get("verdict").asText())));
        same(differ, "watch", log + " verdicts (run, property, verdict)", verdicts(reference), verdicts);
    }

    /**
     * The forecasts of {@code property} watch told in {@code run}: a subsequence of {@code every} forecast of it the
     * replay made, record for record, and what watch printed of them.
     */
    private static void told(List<String> differ, String where, String property, List<ReplayedRun.Timed> every,
                             ReplayedRun run, List<JsonNode> events) {
        List<MonitorEvent.ForecastChanged> told = run.events().stream()
                .filter(MonitorEvent.ForecastChanged.class::isInstance).map(MonitorEvent.ForecastChanged.class::cast)
                .filter(c -> c.deadline() == null && Objects.equals(c.property(), property)).toList();
        Iterator<ReplayedRun.Timed> made = every.iterator();
        for (MonitorEvent.ForecastChanged c : told) {
            boolean found = false;
            while (!found && made.hasNext()) {
                ReplayedRun.Timed t = made.next();
                found = t.line() == c.line() && t.forecast().equals(c.forecast());
            }
            if (!found) {
                differ.add("replay: " + where + " forecast told at line " + c.line() + " is not one it made");
            }
        }
        same(differ, "watch", where + " forecasts (line, probability, time to violation)",
                told.stream().map(c -> printed(c.line(), c.forecast())).toList(),
                ofRun(events, "forecast", run.run()).stream().filter(e -> !e.get("forecast").isNull()
                                && Objects.equals(text(e.get("property")), property))
                        .map(e -> printed(e.get("line").asLong(), e.get("forecast"))).toList());
    }

    /** {@code evaluate}'s replay: each run's forecasts before the violation, its warning and its verdicts. */
    private static void evaluate(List<String> differ, Path log, Paths paths, ReplayedLog reference)
            throws IOException {
        List<RunResult> results = Replay.run(log, "?", false, RunLabel.ALL, -1, paths.models, paths.abstraction, 0,
                paths.confirm, paths.rule);
        if (results.size() != reference.runs().size()) {
            differ.add("evaluate: " + log + " " + results.size() + " runs, the replay " + reference.runs().size());
            return;
        }
        for (int i = 0; i < results.size(); i++) {
            ReplayedRun run = reference.runs().get(i);
            RunResult r = results.get(i);
            String where = log + " run " + i;
            if (r.forecast() != null) {
                same(differ, "evaluate", where + " probabilities", probabilities(run), r.forecast().probabilities());
                same(differ, "evaluate", where + " forecast times", times(run), r.forecast().times());
            }
            MonitorEvent.Warning w = run.outcome().warning();
            same(differ, "evaluate", where + " warning (line, time)", w == null ? null : w.line() + " " + w.time(),
                    r.warningLine() == null ? null : r.warningLine() + " " + r.warningTime());
            MonitorEvent.Violation v = run.outcome().violation();
            same(differ, "evaluate", where + " violation", v == null ? null : v.time(), r.violationTime());
            same(differ, "evaluate", where + " other properties (property, first warning, first violation)",
                    others(run, paths.abstraction), r.properties().stream().map(p -> p.property() + " " + p.warning()
                            + " " + p.violation()).toList());
            for (RunResult.PropertyResult p : r.properties()) {
                if (own(paths).contains(p.property())) {
                    same(differ, "evaluate", where + " " + p.property() + " scored forecasts", toldBefore(run,
                            p.property()), p.forecasts() == null ? List.of() : p.forecasts().probabilities());
                }
            }
        }
    }

    /**
     * The properties with a value or event forecast of their own (not the forecast's property, not a deadline): every
     * bound's and every absence's and precedence's whose training runs taught one.
     */
    private static List<String> own(Paths paths) {
        List<String> ids = new ArrayList<>();
        if (paths.models.forecast() != null) {
            ids.addAll(paths.models.forecast().bounds().keySet());
            paths.models.forecast().events().forEach((id, e) -> {
                if (e.forecasts()) {
                    ids.add(id);
                }
            });
        }
        return ids;
    }

    /** The probabilities of the forecasts of {@code id} the monitor told in {@code run} before its violation. */
    private static List<Double> toldBefore(ReplayedRun run, String id) {
        List<Double> out = new ArrayList<>();
        for (MonitorEvent e : run.events()) {
            if (e instanceof MonitorEvent.Violation v && id.equals(v.property())) {
                break;
            }
            if (e instanceof MonitorEvent.ForecastChanged c && id.equals(c.property()) && c.deadline() == null
                    && c.forecast() != null) {
                out.add(c.forecast().probability());
            }
        }
        return out;
    }

    /** {@code learn}'s held-out replay, given the same models: the forecasts it scores and when the rule warned. */
    private static void learn(List<String> differ, Path log, Paths paths, ReplayedLog reference) throws IOException {
        if (paths.models.forecast() == null) {
            return;
        }
        HeldOutRun.Judged judged = HeldOutRun.replayAll(log, RunLabel.ALL, paths.models, paths.abstraction,
                paths.confirm, paths.rule);
        List<HeldOutRun> held = judged.safety();
        List<ReplayedRun> scored = reference.runs().stream().filter(r -> !r.pairs().isEmpty()).toList();
        if (held.size() != scored.size()) {
            differ.add("learn: " + log + " " + held.size() + " runs, the replay " + scored.size());
            return;
        }
        for (int i = 0; i < held.size(); i++) {
            ReplayedRun run = scored.get(i);
            HeldOutRun h = held.get(i);
            String where = log + " run " + run.run();
            same(differ, "learn", where + " probabilities", probabilities(run), h.probabilities());
            same(differ, "learn", where + " forecast times", times(run), h.times());
            MonitorEvent.Warning w = run.outcome().warning();
            MonitorEvent.Violation v = run.outcome().violation();
            double warned = w != null && (v == null || w.line() < v.line()) ? w.time() : Double.NaN;
            same(differ, "learn", where + " warned at", warned, h.warnedAt());
            same(differ, "learn", where + " violated", run.violated(), h.violated());
            for (String id : own(paths)) {
                HeldOutRun b = judged.bounds().get(id).get(i);
                same(differ, "learn", where + " " + id + " probabilities", run.boundBeforeViolation(id).stream()
                        .map(t -> t.forecast().probability()).toList(), b.probabilities());
                MonitorEvent.Violation bv = run.events().stream().filter(MonitorEvent.Violation.class::isInstance)
                        .map(MonitorEvent.Violation.class::cast).filter(x -> id.equals(x.property())).findFirst()
                        .orElse(null);
                MonitorEvent.Warning bw = run.warnings().stream().filter(x -> id.equals(x.property())).findFirst()
                        .orElse(null);
                double bWarned = bw != null && (bv == null || bw.line() < bv.line()) ? bw.time() : Double.NaN;
                same(differ, "learn", where + " " + id + " warned at", bWarned, b.warnedAt());
                same(differ, "learn", where + " " + id + " violated", bv != null, b.violated());
            }
        }
    }

    /**
     * {@code learn}'s held-out deadline forecasts ({@link HeldOutRun#obligations}, what {@code DeadlineTraining}
     * chooses each deadline's threshold and calibration on), given the same models, against {@code watch}'s: per run
     * and bounded response, every deadline forecast watch tells of an obligation learn judged is one learn has, in
     * order, at the same line with the same calibrated probability and time left (as doubles, as watch's JSON writes
     * them); the deadline warnings and the property's violations are at the lines learn has them.
     */
    private static void deadlines(List<String> differ, Path log, Paths paths, ReplayedLog reference,
                                  List<JsonNode> events) throws IOException {
        if (paths.models.forecast() == null || paths.rule != WarningRule.FORECAST) {
            return; // no deadline forecast without the forecast rule
        }
        List<HeldOutRun> held = HeldOutRun.replayAll(log, RunLabel.ALL, paths.models, paths.abstraction,
                paths.confirm, paths.rule).safety();
        List<ReplayedRun> scored = reference.runs().stream().filter(r -> !r.pairs().isEmpty()).toList();
        if (held.size() != scored.size()) {
            return; // told by learn()
        }
        for (int i = 0; i < held.size(); i++) {
            int run = scored.get(i).run();
            for (Property p : paths.abstraction.properties()) {
                if (!(p instanceof Response r)) {
                    continue;
                }
                Learned learned = Learned.of(held.get(i), r, paths.models.forecast());
                String where = log + " run " + run + " " + r.id();
                List<JsonNode> told = ofRun(events, "forecast", run).stream()
                        .filter(e -> r.id().equals(text(e.get("property"))) && !e.get("deadline").isNull()
                                && e.get("line").asLong() <= learned.lastForecast()).toList();
                paths.deadlines += told.size();
                paths.deadlineWarnings += learned.warnings().size();
                paths.letGo += learned.letGo().size();
                subsequence(differ, where + " deadline forecasts (line, probability, time left)", learned.forecasts(),
                        told.stream().map(e -> deadline(e.get("line").asLong(), e.get("deadline").get("probability")
                                .isNull() ? null : e.get("deadline").get("probability").asDouble(),
                                e.get("deadline").get("timeLeft").asDouble())).toList());
                same(differ, "watch", where + " deadline warnings (line), learn's held-out replay first",
                        learned.warnings(),
                        ofRun(events, "warning", run).stream().filter(e -> r.id().equals(text(e.get("property")))
                                && e.get("clause").asText().equals("deadline")
                                && e.get("line").asLong() <= learned.lastForecast())
                                .map(e -> e.get("line").asLong()).toList());
                same(differ, "watch", where + " violations (line), learn's held-out replay first", learned.letGo(),
                        ofRun(events, "violation", run).stream().filter(e -> r.id().equals(text(e.get("property")))
                                && e.get("line").asLong() <= learned.lastEnd())
                                .map(e -> e.get("line").asLong()).toList());
            }
        }
    }

    /**
     * One run's obligations of one property as learn has them: every deadline forecast (line, probability calibrated
     * by the models' rule, time left), those of each obligation met or missed as {@link DeadlineTraining#heldOut}
     * judges it (the raw probability and the time pending it chooses on), the others' as the held-out replay has
     * them; the lines of the warnings and of the obligations let go still pending (the property's violations), the
     * line of the last forecast and of the last end.
     */
    record Learned(List<String> forecasts, List<Long> warnings, List<Long> letGo, long lastForecast, long lastEnd) {

        static Learned of(HeldOutRun run, Response property, ForecastModel forecast) {
            DeadlineRule rule = forecast.deadlineRule(property.id());
            double deadline = property.within().amount();
            Iterator<DeadlineTraining.HeldOut> judged = DeadlineTraining.heldOut(property.id(), new HeldOutFolds(1,
                    List.of(new HeldOutFolds.Fold(0, forecast.baseRate(), forecast.obligations(), true,
                            List.of(run))))).iterator();
            List<String> forecasts = new ArrayList<>();
            List<Long> warnings = new ArrayList<>();
            List<Long> letGo = new ArrayList<>();
            long lastForecast = -1;
            long lastEnd = -1;
            for (ReplayedRun.Obligation o : run.obligations()) {
                if (!o.property().id().equals(property.id())) {
                    continue;
                }
                DeadlineTraining.HeldOut h = (o.discharged() || o.missed()) && judged.hasNext() ? judged.next() : null;
                int k = 0;
                for (ReplayedRun.Step s : o.forecasts()) {
                    Survival.Estimate e = rule.calibrated(s.estimate());
                    if (h != null && !e.novel()) { // learn's own numbers for what it chooses on
                        double elapsed = h.elapsed().get(k);
                        forecasts.add(deadline(s.line(), rule.calibration().apply(h.probabilities().get(k)),
                                Math.max(0.0, deadline - elapsed)));
                        k++;
                    } else {
                        forecasts.add(deadline(s.line(), e.novel() ? null : e.probability(), e.timeLeft()));
                    }
                    double warnedAt = h != null ? h.caughtAt() : o.warnedAt();
                    if (s.elapsed() == warnedAt) {
                        warnings.add(s.line());
                    }
                    lastForecast = s.line();
                }
                if (!o.discharged()) {
                    letGo.add(o.line());
                }
                lastEnd = o.line();
            }
            return new Learned(forecasts, warnings, letGo, lastForecast, lastEnd);
        }
    }

    /** Adds a disagreement unless {@code told} is, in order, a subsequence of {@code learned}: the first not found. */
    static void subsequence(List<String> differ, String what, List<String> learned, List<String> told) {
        Iterator<String> every = learned.iterator();
        for (String t : told) {
            boolean found = false;
            while (!found && every.hasNext()) {
                found = every.next().equals(t);
            }
            if (!found) {
                differ.add("learn: " + what + ": watch told " + t + ", not one of learn's in order");
                return;
            }
        }
    }

    private static String deadline(long line, Double probability, double timeLeft) {
        return line + " " + probability + " " + timeLeft;
    }

    /** {@code explain --json}: the forecast after each pair, the forecasts scored, the warning and the exit code. */
    private static void explain(List<String> differ, Path log, Paths paths, ReplayedLog reference, int code)
            throws IOException {
        Cli x = Cli.run("explain", "--json", "--log", log.toString(), "--models", paths.dir.toString());
        same(differ, "explain", log + " exit code", code, x.code());
        if (x.code() == ExitCodes.BAD_INPUT) {
            return;
        }
        JsonNode doc = JSON.readTree(x.out());
        List<JsonNode> runs = new ArrayList<>();
        if (doc.has("runs")) {
            doc.get("runs").forEach(runs::add);
        } else {
            runs.add(doc);
        }
        if (runs.size() != reference.runs().size()) {
            differ.add("explain: " + log + " " + runs.size() + " runs, the replay " + reference.runs().size());
            return;
        }
        // evaluate's replay of the same log with the same models: each property's baseline (when the raw-value rule
        // of a bound, the first floor's as any other's, or a deadline's elapsed-time rule warned) as explain gives it
        List<RunResult> evaluated = Replay.run(log, "?", false, RunLabel.ALL, -1, paths.models, paths.abstraction, 0,
                paths.confirm);
        for (int i = 0; i < runs.size(); i++) {
            ReplayedRun run = reference.runs().get(i);
            JsonNode e = runs.get(i);
            String where = log + " run " + i;
            Map<String, Double> baselines = new TreeMap<>();
            e.get("run").get("properties").forEach(p -> baselines.put(p.get("property").asText(),
                    p.get("beyond").isNull() ? null : p.get("beyond").asDouble()));
            Map<String, Double> expectedBaselines = new TreeMap<>();
            evaluated.get(i).properties().forEach(p -> expectedBaselines.put(p.property(), p.beyond()));
            same(differ, "explain", where + " each property's baseline", expectedBaselines, baselines);
            List<String> after = new ArrayList<>();
            e.get("steps").forEach(s -> after.add(s.get("forecast").isNull() ? null
                    : printed(s.get("line").asLong(), s.get("forecast"))));
            List<Forecast> afterPairs = run.afterPairs();
            List<String> expected = new ArrayList<>();
            for (int p = 0; p < run.pairs().size(); p++) {
                expected.add(p < afterPairs.size() ? printed(run.pairs().get(p).pair().reply().line(),
                        afterPairs.get(p)) : null);
            }
            same(differ, "explain", where + " forecast after each pair", expected, after);
            JsonNode forecast = e.get("run").get("forecast");
            if (forecast != null && !forecast.isNull()) {
                List<Double> ps = new ArrayList<>();
                forecast.get("probabilities").forEach(p -> ps.add(p.asDouble()));
                same(differ, "explain", where + " probabilities", probabilities(run), ps);
            }
            for (JsonNode p : e.get("run").get("properties")) {
                String id = p.get("property").asText();
                if (own(paths).contains(id)) {
                    List<Double> ps = new ArrayList<>();
                    p.path("forecasts").path("probabilities").forEach(q -> ps.add(q.asDouble()));
                    same(differ, "explain", where + " " + id + " scored forecasts", toldBefore(run, id), ps);
                }
            }
            // explain tells the run's first warning of any property, as the monitor raised it
            MonitorEvent.Warning w = run.outcome().firstWarning();
            same(differ, "explain", where + " warning", w == null ? null : w.reason(), text(e.get("warning")));
            JsonNode wl = e.get("run").get("warningLine");
            w = run.outcome().warning(); // the run's fields are the forecast property's (kept as deprecated aliases)
            same(differ, "explain", where + " warning line", w == null ? null : w.line(),
                    wl == null || wl.isNull() ? null : wl.asLong());
        }
    }

    /** {@code classify --json}: watch's verdict at the end of the file, and whether each run violated. */
    private static void classify(List<String> differ, Path log, Paths paths, ReplayedLog reference, int code)
            throws IOException {
        Cli c = Cli.run("classify", "--json", "--log", log.toString(), "--models", paths.dir.toString());
        same(differ, "classify", log + " exit code", code, c.code());
        if (c.code() == ExitCodes.BAD_INPUT) {
            return;
        }
        JsonNode doc = JSON.readTree(c.out());
        List<JsonNode> runs = new ArrayList<>();
        if (doc.has("runs")) {
            doc.get("runs").forEach(runs::add);
        } else {
            runs.add(doc);
        }
        List<ReplayedRun> judged = reference.runs().size() > 1
                ? reference.runs().stream().filter(r -> !r.pairs().isEmpty()).toList() : reference.runs();
        same(differ, "classify", log + " violated per run", judged.stream().map(ReplayedRun::violated).toList(),
                runs.stream().map(r -> r.get("violated").asBoolean()).toList());
        for (JsonNode r : runs) {
            same(differ, "classify", log + " watch's exit", code, r.get("watchExit").asInt());
        }
    }

    /** Adds what differs between what the replay gave and what {@code path} gave, the first difference named. */
    static void same(List<String> differ, String path, String what, Object replayed, Object other) {
        if (Objects.equals(replayed, other)) {
            return;
        }
        String detail = "";
        if (replayed instanceof List<?> a && other instanceof List<?> b) {
            int i = 0;
            while (i < Math.min(a.size(), b.size()) && Objects.equals(a.get(i), b.get(i))) {
                i++;
            }
            detail = i < Math.min(a.size(), b.size()) ? ": item " + i + " is " + a.get(i) + " in the replay, "
                    + b.get(i) + " in " + path : ": " + a.size() + " in the replay, " + b.size() + " in " + path;
        } else {
            detail = ": " + replayed + " in the replay, " + other + " in " + path;
        }
        differ.add(path + ": " + what + detail);
    }

    private static List<Double> probabilities(ReplayedRun run) {
        return run.beforeViolation().stream().map(t -> t.forecast().probability()).toList();
    }

    private static List<Double> times(ReplayedRun run) {
        return run.beforeViolation().stream().map(ReplayedRun.Timed::time).toList();
    }

    private static List<String> verdicts(ReplayedLog reference) {
        List<String> out = new ArrayList<>();
        for (ReplayedRun run : reference.runs()) {
            run.outcome().properties().forEach(p -> out.add(run.run() + " " + p.property().id() + " "
                    + p.verdict().id()));
        }
        return out;
    }

    /** Every property but the forecast's, with its first warning and violation in the run, from the events. */
    private static List<String> others(ReplayedRun run, Abstraction abstraction) {
        String forecast = abstraction.safety().map(b -> b.id()).orElse(null);
        List<String> out = new ArrayList<>();
        abstraction.properties().stream().filter(p -> !p.id().equals(forecast)).forEach(p -> {
            Double warning = run.warnings().stream().filter(w -> p.id().equals(w.property())).findFirst()
                    .map(MonitorEvent.Warning::time).orElse(null);
            Double violation = run.events().stream().filter(MonitorEvent.Violation.class::isInstance)
                    .map(MonitorEvent.Violation.class::cast).filter(v -> p.id().equals(v.property())).findFirst()
                    .map(MonitorEvent.Violation::time).orElse(null);
            out.add(p.id() + " " + warning + " " + violation);
        });
        return out;
    }

    private static String printed(long line, Forecast f) {
        return String.format(Locale.ROOT, "%d %s %s", line, round(f.probability()),
                ForecastWords.inSight(f) ? round(f.timeToViolation()) : null);
    }

    private static String printed(long line, JsonNode f) {
        JsonNode t = f.get("timeToViolation");
        return String.format(Locale.ROOT, "%d %s %s", line, f.get("probability").asDouble(),
                t.isNull() ? null : t.asDouble());
    }

    private static String warning(long line, String clause, String property, Double probability) {
        return line + " " + clause + " " + property + " " + probability;
    }

    /** As watch's JSON writes a forecast's numbers: to four decimals. */
    private static double round(double x) {
        return Math.round(x * 1e4) / 1e4;
    }

    private static String text(JsonNode n) {
        return n == null || n.isNull() ? null : n.asText();
    }

    private static List<JsonNode> ofRun(List<JsonNode> events, String kind, int run) {
        return events.stream().filter(e -> e.get("event").asText().equals(kind) && e.has("run")
                && e.get("run").asInt() == run).toList();
    }

    private static List<Path> files(Path dir, String suffix) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            List<Path> files = s.filter(p -> p.toString().endsWith(suffix)).sorted().toList();
            assertFalse(files.isEmpty(), dir + " holds no " + suffix);
            return files;
        }
    }
}
