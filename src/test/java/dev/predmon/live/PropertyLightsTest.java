package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.event.LogEvent;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.Scorecard;
import dev.predmon.forecast.Survival;
import dev.predmon.model.LearnedModel;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PropertyStatus;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Deadline;
import dev.predmon.property.Property;
import dev.predmon.property.Verdict;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * One light per property on a tile, worst first, in {@code /status} and {@code /metrics}: an absence violated is red
 * with its event, a pending obligation is green with its deadline forecast, a deadline warned is yellow until its
 * response comes (recovered), a property of which nothing is known yet is grey, never green. The statuses are the
 * monitor's as it hands them over after each record; the cases are written by hand.
 */
class PropertyLightsTest {

    private static final Abstraction A = AbstractionFiles.defaults();
    private final AtomicLong now = new AtomicLong(1_000_000);

    private Board board() {
        return new Board(List.<LearnedModel>of(), A.safety(), A.properties(), Duration.ofSeconds(10), now::get,
                RobotNames.byFile(), List.of());
    }

    private static Property property(String id) {
        return A.properties().stream().filter(p -> p.id().equals(id)).findFirst().orElseThrow();
    }

    private static LogRecord level(double time, double level) {
        return new Records().at(time).level(level).list().get(1);
    }

    /** Every property holding, but those of {@code changed}, as the monitor gives them. */
    private static List<PropertyStatus> statuses(Map<String, PropertyStatus> changed) {
        List<PropertyStatus> all = new ArrayList<>();
        for (Property p : A.properties()) {
            PropertyStatus.Model model = p.id().equals("battery") ? PropertyStatus.Model.FORECAST
                    : PropertyStatus.Model.NONE;
            all.add(changed.getOrDefault(p.id(), new PropertyStatus(p, Verdict.HOLDS, model, false, null, null)));
        }
        return all;
    }

    private static JsonNode lights(Board b) {
        return b.status("a.log").get("logs").get(0).get("properties");
    }

    private static String ids(JsonNode lights) {
        List<String> s = new ArrayList<>();
        lights.forEach(l -> s.add(l.get("property").asText() + " " + l.get("state").asText()));
        return String.join(", ", s);
    }

    @Test
    void beforeTheFirstRecordNothingIsKnownSoEveryLightIsGreyNotGreen() {
        Board b = board();
        b.tile("a.log");
        JsonNode lights = lights(b);
        assertEquals(5, lights.size());
        lights.forEach(l -> assertEquals("grey", l.get("light").asText(), l.toString()));
    }

    @Test
    void modelsThatDoNotFitTheLogGiveNoGreenLight() {
        Board b = board();
        Tile t = b.tile("a.log");
        Judged.record(t, level(1, 80));
        t.properties(statuses(Map.of()));
        assertEquals("green", lights(b).get(0).get("light").asText());
        t.noVerdict("the models' abstraction does not fit this log");
        JsonNode lights = lights(b);
        lights.forEach(l -> assertEquals("grey", l.get("light").asText(), l.toString()));
        assertEquals("no verdict: the models cannot judge this log", lights.get(1).get("words").asText());
    }

    /**
     * A property none of whose records occurred in the run (no grasp tried; the battery on a misspelt command) is a
     * grey light that says so, never a green "holds", in /status and /metrics.
     */
    @Test
    void aPropertyWithNoEvidenceIsGreyNotGreen() {
        Board b = board();
        Tile t = b.tile("a.log");
        Judged.record(t, level(1, 80));
        Verdict none = new Verdict.NoEvidence("no ArmService/closeHand command (its trigger) in the run");
        Verdict unread = new Verdict.NoEvidence("no reading of BatteryReader/levle in the run");
        t.properties(statuses(Map.of("grasp-in-time", new PropertyStatus(property("grasp-in-time"), none,
                PropertyStatus.Model.NONE, false, null, null), "battery", new PropertyStatus(property("battery"),
                unread, PropertyStatus.Model.FORECAST, false, null, null))));
        JsonNode lights = lights(b);
        assertEquals("battery no-evidence, grasp-in-time no-evidence, charger-in-time holds, no-abort holds, "
                + "navigation-in-time holds", ids(lights), "grey before green");
        JsonNode grasp = lights.get(1);
        assertEquals("grey", grasp.get("light").asText());
        assertEquals("no-evidence", grasp.get("verdict").asText());
        assertEquals("no evidence (no ArmService/closeHand command (its trigger) in the run)",
                grasp.get("words").asText());
        assertEquals("grey", lights.get(0).get("light").asText(), "the forecast's property too");
        assertEquals("no evidence (no reading of BatteryReader/levle in the run)", lights.get(0).get("words").asText());
        String metrics = new String(b.metrics().scrape(), StandardCharsets.UTF_8);
        assertTrue(metrics.contains("predmon_property_state{log=\"a.log\",property=\"grasp-in-time\",robot=\"a\","
                + "state=\"no-evidence\"} 1.0"), metrics);
        assertTrue(metrics.contains("predmon_property_state{log=\"a.log\",property=\"grasp-in-time\",robot=\"a\","
                + "state=\"holds\"} 0.0"), metrics);
    }

    /**
     * An absence's event forecast is on its light as a bound's value forecast is (a probability, no value, and no
     * countdown while it does not warn: its rule does not expect the violation);
     * one the training runs could not teach says why.
     */
    @Test
    void anAbsencesForecastIsOnItsLightAndOneWithoutSaysWhy() {
        Board b = board();
        Tile t = b.tile("a.log");
        Judged.record(t, level(1, 80));
        Forecast f = new Forecast(0.62, 40.0, 20.0, 90.0, Forecast.Basis.MATCHED, null, 8, 5, null, null, "s");
        t.properties(statuses(Map.of("no-abort", new PropertyStatus(property("no-abort"), Verdict.HOLDS,
                PropertyStatus.Model.FORECAST, false, null, null, f))));
        JsonNode light = light(lights(b), "no-abort");
        assertEquals("forecast", light.get("model").asText());
        assertEquals(0.62, light.get("forecast").get("probability").asDouble(), 1e-9);
        assertTrue(light.get("forecast").get("value").isNull(), light.toString());
        assertEquals("P(violation) 62%, no warning (skill not measured)",
                light.get("forecastWords").asText());

        t.properties(statuses(Map.of("no-abort", new PropertyStatus(property("no-abort"), Verdict.HOLDS,
                PropertyStatus.Model.NONE, false, null, null, null, "never violated in 43 training runs"))));
        assertEquals("no forecast: never violated in 43 training runs",
                light(lights(b), "no-abort").get("forecastWords").asText());
    }

    private static JsonNode light(JsonNode lights, String id) {
        for (JsonNode l : lights) {
            if (l.get("property").asText().equals(id)) {
                return l;
            }
        }
        throw new AssertionError("no light of " + id + " in " + lights);
    }

    @Test
    void anAbortIsARedLightOfNoAbortWithItsEventFirstWhileTheBatteryStaysGreen() {
        Board b = board();
        Tile t = b.tile("a.log");
        Tile calm = b.tile("b.log");
        Judged.record(t, level(1, 80));
        Judged.record(calm, level(1, 80));
        calm.properties(statuses(Map.of()));
        Verdict.Violated abort = new Verdict.Violated(157, 5, null, null, "GoTo/getStatus reply 3");
        t.properties(statuses(Map.of("no-abort", new PropertyStatus(property("no-abort"), abort,
                PropertyStatus.Model.NONE, false, null, null))));
        b.event(t, LogEvent.of("a.log", new MonitorEvent.Violation(5, 157, "no-abort", "navigation never aborts", null, null,
                "GoTo/getStatus reply 3", Clock.SECONDS, 0, false)));

        JsonNode lights = lights(b);
        assertEquals("no-abort violated, battery holds, charger-in-time holds, navigation-in-time holds, "
                + "grasp-in-time holds", ids(lights), "worst first, then the abstraction's order");
        JsonNode red = lights.get(0);
        assertEquals("red", red.get("light").asText());
        assertEquals("navigation never aborts", red.get("name").asText());
        assertEquals(157, red.get("line").asLong());
        assertEquals("violated at line 157: GoTo/getStatus reply 3", red.get("words").asText());
        assertEquals("no forecast: no model of this property", red.get("forecastWords").asText());
        JsonNode tile = b.status("a.log").get("logs").get(0);
        assertEquals("violation", tile.get("state").asText(), "the robot's state is its worst property's");
        assertEquals("red", tile.get("light").asText());
        assertEquals("ok", tile.get("forecastState").asText(), "the battery, the forecast's property, holds");
        assertEquals("[\"no-abort\"]", tile.get("violated").toString());
        assertEquals("no-abort", tile.get("worst").get("property").asText());
        assertEquals("a.log", b.status(null).get("logs").get(0).get("log").asText(),
                "a robot with a property violated sorts before one whose properties all hold");

        String metrics = new String(b.metrics().scrape(), StandardCharsets.UTF_8);
        assertTrue(metrics.contains("predmon_property_state{log=\"a.log\",property=\"no-abort\",robot=\"a\","
                + "state=\"violated\"} 1.0"), metrics);
        assertTrue(metrics.contains("predmon_property_state{log=\"a.log\",property=\"battery\",robot=\"a\","
                + "state=\"holds\"} 1.0"), metrics);
        assertTrue(metrics.contains("predmon_property_violations_total{log=\"a.log\",property=\"no-abort\","
                + "robot=\"a\"} 1.0"), metrics);
        assertTrue(metrics.contains("predmon_property_violations_total{log=\"b.log\",property=\"no-abort\","
                + "robot=\"b\"} 0.0"), "counted from 0: " + metrics);
        assertTrue(metrics.contains("predmon_violations_total{log=\"a.log\",property=\"battery level >= 20% (thesis "
                + "3.3.1)\",robot=\"a\"} 0.0"), "the battery's metric keeps its name and label: " + metrics);
    }

    @Test
    void aPendingNavigationIsGreenWithItsChanceOfAMissAndTimeLeft() {
        Board b = board();
        Tile t = b.tile("a.log");
        Judged.record(t, level(1, 80));
        // pending since tick 1, due by tick 401; after 100 ticks 8 training navigations were still pending, 1 of them
        // past the deadline: P(miss) 0.12 with the prior, 300 ticks left
        Verdict.Pending pending = new Verdict.Pending(24, 1, 401, Deadline.Unit.TICKS);
        t.properties(statuses(Map.of("navigation-in-time", new PropertyStatus(property("navigation-in-time"), pending,
                PropertyStatus.Model.DEADLINE, false, new Survival.Estimate(0.12, 300, 8, 1, false), "ticks"))));
        assertEquals("navigation-in-time pending, battery holds, charger-in-time holds, no-abort holds, grasp-in-time "
                + "holds", ids(lights(b)), "green both, a pending obligation before what simply holds");
        JsonNode nav = lights(b).get(0);
        assertEquals("pending", nav.get("state").asText());
        assertEquals("green", nav.get("light").asText(), "the robot's ordinary work, going as the training runs did");
        assertEquals("pending since line 24 (tick 1 of the run, due by tick 401)", nav.get("words").asText());
        assertEquals(0.12, nav.get("forecast").get("probability").asDouble());
        assertEquals(300, nav.get("forecast").get("timeLeft").asDouble());
        assertEquals("ticks", nav.get("forecast").get("unit").asText());
        assertTrue(nav.get("skill").isNull(), "a deadline's skill is not measured");
        assertEquals("P(miss) 12%, 300 ticks left (skill not measured)", nav.get("forecastWords").asText());
        String metrics = new String(b.metrics().scrape(), StandardCharsets.UTF_8);
        assertTrue(metrics.contains("predmon_property_probability{log=\"a.log\",property=\"navigation-in-time\","
                + "robot=\"a\"} 0.12"), metrics);
        assertTrue(metrics.contains("predmon_property_time_left{log=\"a.log\",property=\"navigation-in-time\","
                + "robot=\"a\",unit=\"ticks\"} 300.0"), metrics);

        // past every training navigation: no evidence, grey with its words and the time left, no number
        t.properties(statuses(Map.of("navigation-in-time", new PropertyStatus(property("navigation-in-time"), pending,
                PropertyStatus.Model.DEADLINE, false, new Survival.Estimate(Double.NaN, 66, 0, 0, true), "ticks"))));
        nav = lights(b).get(0);
        assertEquals("navigation-in-time unknown", nav.get("property").asText() + " " + nav.get("state").asText());
        assertEquals("grey", nav.get("light").asText());
        assertTrue(nav.get("forecast").get("probability").isNull());
        assertEquals("no forecast: pending longer than any training obligation; 66 ticks left",
                nav.get("forecastWords").asText());
    }

    @Test
    void aDeadlineForecastWithoutSkillIsNoHeadline() {
        // the navigation's scorecard: Brier 0.30 against 0.20 for the base rate, no skill
        Scorecard none = new Scorecard("a navigation ends within 400 ticks", 5, 50, 3, 1, 2, 12, "ticks", 0.30, 0.20);
        Board b = new Board(List.<LearnedModel>of(), A.safety(), A.properties(), Duration.ofSeconds(10), now::get,
                RobotNames.byFile(), List.of(none));
        Tile t = b.tile("a.log");
        Judged.record(t, level(1, 80));
        t.properties(statuses(Map.of("navigation-in-time", new PropertyStatus(property("navigation-in-time"),
                new Verdict.Pending(24, 1, 401, Deadline.Unit.TICKS), PropertyStatus.Model.DEADLINE, false,
                new Survival.Estimate(0.12, 300, 8, 1, false), "ticks"))));
        JsonNode nav = lights(b).get(0);
        assertEquals(false, nav.get("skill").asBoolean(true), nav.toString());
        assertEquals("no skill: the deadline forecast did no better than the base rate; 300 ticks left",
                nav.get("forecastWords").asText());
    }

    @Test
    void aDeadlineWarnedThenDischargedIsYellowThenGreenWithItsRecoveryAndTheBatteryAlarmIsUntouched() {
        Board b = board();
        Tile t = b.tile("a.log");
        Judged.record(t, level(1, 80));
        Property nav = property("navigation-in-time");
        Verdict.Pending pending = new Verdict.Pending(24, 1, 401, Deadline.Unit.TICKS);
        Survival.Estimate e = new Survival.Estimate(0.62, 20, 5, 2, false);
        String reason = "'a navigation ends within 400 ticks' (navigation-in-time) pending 380 ticks; 2 of the 5 "
                + "training obligations pending that long took longer than 400 ticks; P(miss) 0.62; 20 ticks left";
        b.event(t, LogEvent.of("a.log", new MonitorEvent.Warning(381, 900, List.of(), 80.0, 3, Clock.TICKS, 0, WarningRule.FORECAST, null,
                reason, MonitorEvent.Clause.DEADLINE, null, "navigation-in-time", e)));
        t.properties(statuses(Map.of("navigation-in-time", new PropertyStatus(nav, pending,
                PropertyStatus.Model.DEADLINE, true, e, "ticks"))));
        JsonNode yellow = lights(b).get(0);
        assertEquals("navigation-in-time warning", yellow.get("property").asText() + " "
                + yellow.get("state").asText());
        assertEquals("yellow", yellow.get("light").asText());
        assertEquals(reason, yellow.get("words").asText());
        assertEquals("warning", b.status("a.log").get("logs").get(0).get("worst").get("state").asText());

        b.event(t, LogEvent.of("a.log", new MonitorEvent.Recovered(390, 950, "discharged", Double.NaN, "'a navigation "
                + "ends within 400 ticks' (navigation-in-time): the response came in time; the deadline warning is over",
                Clock.TICKS, 0, "navigation-in-time")));
        t.properties(statuses(Map.of("navigation-in-time", new PropertyStatus(nav, Verdict.HOLDS,
                PropertyStatus.Model.DEADLINE, false, null, "ticks"))));
        JsonNode tile = b.status("a.log").get("logs").get(0);
        JsonNode green = tile.get("properties").get(3);
        assertEquals("navigation-in-time holds", green.get("property").asText() + " " + green.get("state").asText(),
                ids(tile.get("properties")));
        assertTrue(green.get("recovery").asText().contains("the response came in time"), green.toString());
        assertEquals("no forecast: no obligation pending", green.get("forecastWords").asText());
        assertEquals("ok", tile.get("state").asText());
        assertFalse(tile.get("recovered").asBoolean(), "the battery's alarm is the battery's: " + tile);
        assertEquals(2, tile.get("events").size(), "the warning and its recovery are among the last events");
    }
}
