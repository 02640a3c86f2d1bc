package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.event.LogEvent;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.model.LearnedModel;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The states an operator reads on a tile, and {@code /status} with the forecast: unknown where the models cannot judge,
 * a run that ended apart from a log that stopped mid-run, a violation that recovers, the warning's reason and the
 * property's action, the robot's name, worst first.
 */
class TileStateTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Abstraction A = AbstractionFiles.defaults();
    private final AtomicLong now = new AtomicLong(1_000_000);

    private Board board(RobotNames names) {
        return new Board(List.<LearnedModel>of(), A.safety(), Duration.ofSeconds(10), now::get, names);
    }

    private Board board() {
        return board(RobotNames.byFile());
    }

    private static LogRecord level(double time, double level) {
        return new Records().at(time).level(level).list().get(1);
    }

    /** The tree starting or stopping a skill, as the monitor logs it (protocol Skill_request, dropped by the abstraction). */
    private static List<LogRecord> skill(String skill, String command) {
        return new Records().call("/" + skill + "/BT_rpc/client", "/" + skill + "/BT_rpc/server", "Skill_request",
                command, "", "").list();
    }

    private static Forecast forecast(double p, Double ttv, Forecast.Basis basis, Long novelSince) {
        return new Forecast(p, ttv, ttv == null ? null : ttv * 0.9, ttv == null ? null : ttv * 1.2, basis, novelSince,
                12, 9, 31.5, -2.4, "s");
    }

    /** A forecast object as {@code watch --json} prints it (the fields of event.ForecastJson). */
    private static ObjectNode forecastJson(Forecast f) {
        ObjectNode j = JSON.createObjectNode().put("probability", f.probability());
        j.put("timeToViolation", f.timeToViolation()).put("low", f.low()).put("high", f.high()).put("unit", f.unit())
                .put("basis", f.basis().label()).put("novelSince", f.novelSince()).put("runs", f.runs())
                .put("violated", f.violated()).put("value", f.value()).put("drift", f.drift())
                .put("explanation", ForecastWords.line(f));
        return j;
    }

    private static JsonNode snap(Board b, String log) {
        return b.status(log).get("logs").get(0);
    }

    private static String state(Board b, String log) {
        return snap(b, log).get("state").asText();
    }

    @Test
    void noModelMatchingOrNovelBehaviourIsUnknownNeitherGreenNorRed() {
        Board b = board();
        Tile t = b.tile("a.log");
        Judged.record(t, level(1, 80));
        assertEquals("ok", state(b, "a.log"));
        assertEquals("green", snap(b, "a.log").get("light").asText());
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.NoMatch(5, 40, Clock.SECONDS, 0)));
        JsonNode s = snap(b, "a.log");
        assertEquals("unknown", s.get("state").asText());
        assertEquals("blue", s.get("light").asText());
        assertEquals(40, s.get("noMatchLine").asLong());

        Tile n = b.tile("b.log");
        Judged.record(n, level(1, 80));
        Forecast novel = forecast(0.4, 60.0, Forecast.Basis.RESYNCHRONISED, 33L);
        b.event(n, LogEvent.of(n.log(), new MonitorEvent.ForecastChanged(2, 50, novel, Clock.SECONDS, 0)));
        assertEquals("unknown", state(b, "b.log"), "novel behaviour: matching resumed, but on less evidence");
        Forecast valueOnly = forecast(0.4, 60.0, Forecast.Basis.VALUE_ONLY, null);
        b.event(n, LogEvent.of(n.log(), new MonitorEvent.ForecastChanged(3, 60, valueOnly, Clock.SECONDS, 0)));
        assertEquals("unknown", state(b, "b.log"));
        Forecast matched = forecast(0.4, 60.0, Forecast.Basis.MATCHED, null);
        b.event(n, LogEvent.of(n.log(), new MonitorEvent.ForecastChanged(4, 70, matched, Clock.SECONDS, 0)));
        assertEquals("ok", state(b, "b.log"), "matched again: the forecast is trusted again");
        assertEquals(0, snap(b, "b.log").get("events").size(), "forecasts are shown, not listed as events");

        // A forecast-rule warning with no scenario left: a warning, not unknown, with its reason and the action.
        Forecast high = forecast(0.97, 5.0, Forecast.Basis.VALUE_ONLY, 20L);
        String reason = "P(violation) 0.97 reaches the warning threshold 0.92; about 5.00 s to the violation";
        MonitorEvent.Warning w = new MonitorEvent.Warning(6, 80, List.of(), 31.5, 9, Clock.SECONDS, 0,
                WarningRule.FORECAST, high, reason);
        b.event(t, LogEvent.of(t.log(), w));
        s = snap(b, "a.log");
        assertEquals("warning", s.get("state").asText());
        assertEquals(reason, s.get("warning").get("reason").asText());
        assertEquals("forecast", s.get("warning").get("rule").asText());
        assertEquals(0, s.get("warning").get("scenarios").size());
        assertEquals("send the robot to the charging station", s.get("action").asText());
        assertEquals(0.97, s.get("forecast").get("probability").asDouble());
    }

    @Test
    void statusCarriesTheForecastAsWatchJsonPrintsIt() {
        Board b = board();
        Tile t = b.tile("r.log");
        Judged.record(t, level(1, 35));
        Forecast f = forecast(0.71, 6.88, Forecast.Basis.MATCHED, null);
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.ForecastChanged(2, 90, f, Clock.SECONDS, 0)));
        JsonNode fj = snap(b, "r.log").get("forecast");
        assertEquals(forecastJson(f), fj, "the same object, field for field");
        List<String> fields = new ArrayList<>();
        fj.fieldNames().forEachRemaining(fields::add);
        assertEquals(List.of("probability", "timeToViolation", "low", "high", "unit", "basis", "novelSince", "runs",
                "violated", "value", "drift", "explanation"), fields);

        b.event(t, LogEvent.of(t.log(), new MonitorEvent.RunStarted(1, 100, 500, Clock.SECONDS)));
        JsonNode s = snap(b, "r.log");
        assertTrue(s.get("forecast").isNull(), "a new run has no forecast yet");
        assertEquals(0.71, s.get("earlierRuns").get(0).get("probability").asDouble(), "the run's last forecast");
    }

    @Test
    void aRunThatEndsAtRestIsEndedAndOneThatStopsMidRunIsStale() {
        Board b = board();
        Tile done = b.tile("done.log");
        Tile dead = b.tile("dead.log");
        for (Tile t : List.of(done, dead)) {
            skill("GoToDestination", "send_start").forEach(r -> Judged.record(t, r));
            Judged.record(t, level(1, 80));
        }
        skill("GoToDestination", "send_stop").forEach(r -> Judged.record(done, r));
        now.addAndGet(9_000);
        assertEquals("ok", state(b, "done.log"), "quiet for less than the stale time");
        assertEquals("ok", state(b, "dead.log"));
        now.addAndGet(1_000);
        JsonNode ended = snap(b, "done.log");
        assertEquals("ended", ended.get("state").asText());
        assertFalse(ended.get("stale").asBoolean(), "a run that ended is not stale");
        JsonNode stale = snap(b, "dead.log");
        assertEquals("ok", stale.get("state").asText());
        assertTrue(stale.get("stale").asBoolean());
        assertEquals(List.of("GoToDestination"), List.of(stale.get("running").get(0).asText()));
        assertEquals(List.of("dead.log", "done.log"), order(b), "quiet mid-run sorts before a run that ended");

        b.grew(done);
        assertEquals("ok", state(b, "done.log"), "it grows again: a new run is under way");
        Tile capture = b.tile("capture.log"); // no tree-to-skill traffic: it cannot tell, and stays stale
        Judged.record(capture, level(1, 80));
        now.addAndGet(10_000);
        assertTrue(snap(b, "capture.log").get("stale").asBoolean());
        assertTrue(snap(b, "capture.log").get("treeAtRest").isNull());
    }

    @Test
    void aViolationThatRecoversShowsWhatHoldsNowAndKeepsTheViolationInTheHistory() {
        Board b = board();
        Tile t = b.tile("r.log");
        Judged.record(t, level(1, 25));
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Violation(2, 20, "battery", 19.95, 20.1, Clock.SECONDS, 0)));
        Judged.record(t, level(2, 19.95));
        assertEquals("violation", state(b, "r.log"));
        Judged.record(t, level(30, 96.7));
        assertEquals("violation", state(b, "r.log"), "the monitor decides when it holds again, not the tile");
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Recovered(30, 40, "property", 96.7, "the property holds again", Clock.SECONDS, 0)));
        JsonNode s = snap(b, "r.log");
        assertEquals("ok", s.get("state").asText(), "it holds again");
        assertTrue(s.get("recovered").asBoolean());
        assertEquals("property", s.get("recovery").get("cause").asText());
        assertEquals(19.95, s.get("violation").get("value").asDouble(), "the violation stays");
        assertEquals(List.of("violation", "recovered"), moments(s));
        assertEquals(96.7, s.get("history").get(1).get("value").asDouble());
        assertEquals(96.7, s.get("recovery").get("value").asDouble());
        assertEquals(96.7, s.get("recovery").get("battery").asDouble(), "the older name stays");
        Judged.record(t, level(40, 12));
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Violation(40, 50, "battery", 12, 96.7, Clock.SECONDS, 0)));
        s = snap(b, "r.log");
        assertEquals("violation", s.get("state").asText());
        assertEquals(List.of("violation", "recovered", "violated again"), moments(s));
    }

    @Test
    void aWarningWhoseCauseEndedIsGoneItsTimeStaysAndUnderWaySaysSince() {
        Board b = board();
        Tile t = b.tile("r.log");
        Judged.record(t, level(1, 40));
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.UnderWay(5, 30, "skill GoToChargingStation", true, Clock.SECONDS, 0)));
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Warning(6, 35, List.of(), 29.6, 3, Clock.SECONDS, 0)));
        JsonNode s = snap(b, "r.log");
        assertEquals("warning", s.get("state").asText());
        assertEquals(5.0, s.get("underWay").get("since").asDouble());
        assertEquals("matching", s.get("warning").get("clause").asText());
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Recovered(9, 60, "action", 45, "recovered by the action", Clock.SECONDS, 0)));
        s = snap(b, "r.log");
        assertEquals("ok", s.get("state").asText(), "no warning state after the recovery");
        assertEquals(List.of("warning", "recovered"), moments(s), "the warning's time stays in this run");
        assertEquals(6.0, s.get("history").get(0).get("time").asDouble());
    }

    @Test
    void modelsThatDoNotFitShowNoVerdictAndNoForecastAndAMissingLogSaysSo() {
        Board b = board();
        Tile t = b.tile("r.log");
        Judged.record(t, level(1, 40));
        t.noVerdict("the abstraction does not fit this log; learn with --abstraction scope-fetch");
        JsonNode s = snap(b, "r.log");
        assertEquals("no-verdict", s.get("state").asText());
        assertTrue(s.get("noVerdict").asText().contains("--abstraction scope-fetch"));
        assertTrue(s.get("forecast").isNull());
        b.tile("/nowhere/robot.log");
        assertFalse(snap(b, "/nowhere/robot.log").get("exists").asBoolean());
        assertTrue(snap(b, "r.log").get("exists").asBoolean(), "a log with records exists");
    }

    @Test
    void worstFirstWithTheRobotsNamesAndWhatIsWatched() {
        Board b = board(RobotNames.pattern("{dir}"));
        b.watching(List.of("logs in /robots"));
        assertEquals("logs in /robots", b.status(null).get("watching").get(0).asText());
        assertEquals(0, b.status(null).get("logs").size(), "nothing yet: the page says what it waits for");
        Tile ok = b.tile("/robots/r1/monitor.log");
        Judged.record(ok, level(1, 80));
        Tile warned = b.tile("/robots/r2/monitor.log");
        Judged.record(warned, level(1, 40));
        b.event(warned, LogEvent.of(warned.log(), new MonitorEvent.Warning(3, 30, List.of("depleted"), 40.0, 4, Clock.SECONDS, 0)));
        b.tile("/robots/r3/monitor.log");
        Tile red = b.tile("/robots/r4/monitor.log");
        b.event(red, LogEvent.of(red.log(), new MonitorEvent.Violation(2, 20, "battery", 12, 20.1, Clock.SECONDS, 0)));
        Tile unknown = b.tile("/robots/r5/monitor.log");
        Judged.record(unknown, level(1, 80));
        b.event(unknown, LogEvent.of(unknown.log(), new MonitorEvent.NoMatch(5, 40, Clock.SECONDS, 0)));
        List<String> names = new ArrayList<>();
        List<String> states = new ArrayList<>();
        b.status(null).get("logs").forEach(s -> {
            names.add(s.get("name").asText());
            states.add(s.get("state").asText());
        });
        assertEquals(List.of("r4", "r2", "r5", "r1", "r3"), names);
        assertEquals(List.of("violation", "warning", "unknown", "ok", "waiting"), states);
    }

    @Test
    void robotNamesComeFromTheOptionOrThePath() {
        assertEquals("r1", RobotNames.byFile().of("logs/r1.log"));
        assertEquals("r1", RobotNames.pattern("{dir}").of("robots/r1/monitor.log"));
        assertEquals("r1-monitor", RobotNames.pattern("{dir}-{file}").of("robots/r1/monitor.txt"));
        assertEquals("Marvin", RobotNames.fixed(" Marvin ").of("whatever.log"));
        assertThrows(IllegalArgumentException.class, () -> RobotNames.pattern("{robot}"));
        assertThrows(IllegalArgumentException.class, () -> RobotNames.pattern("robot"));
        assertThrows(IllegalArgumentException.class, () -> RobotNames.fixed(" "));
    }

    private static List<String> moments(JsonNode tile) {
        List<String> out = new ArrayList<>();
        tile.get("history").forEach(m -> out.add(m.get("what").asText()));
        return out;
    }

    private static List<String> order(Board b) {
        List<String> out = new ArrayList<>();
        b.status(null).get("logs").forEach(s -> out.add(s.get("log").asText()));
        return out;
    }
}
