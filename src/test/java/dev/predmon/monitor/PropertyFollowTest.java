package dev.predmon.monitor;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.forecast.BoundModel;
import dev.predmon.forecast.Calibration;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.Lows;
import dev.predmon.forecast.Survival;
import dev.predmon.matching.Matching;
import dev.predmon.model.ModelIndex;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.property.Bound;
import dev.predmon.property.Deadline;
import dev.predmon.property.Event;
import dev.predmon.property.Property;
import dev.predmon.property.RecordMatch;
import dev.predmon.property.Response;
import dev.predmon.property.Scope;
import dev.predmon.property.ValueReader;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * The follower layer on hand-made records and hand-made forecasts, one property kind at a time: what a sequence of
 * readings (or of ticks) makes of warnings, violations and recoveries. No learned machine: no nominal model matches,
 * so the forecast rule's novelty clause warns at each new value past every safe training run's extreme, and a
 * threshold above 1 keeps its probability clause out, so that every warning is computed by hand.
 */
class PropertyFollowTest {

    private static final ValueReader LEVEL = AbstractionFiles.defaults().safety().orElseThrow().value();
    private static final ModelIndex INDEX = new ModelIndex(ModelIndex.FORMAT,
            new ModelIndex.AbstractionInfo("test", "f", null, null), List.of(), List.of());
    private static final Bound FLOOR = new Bound("floor", "level >= 20", null, Scope.GLOBAL, LEVEL, 20,
            Double.POSITIVE_INFINITY);
    private static final Bound CEILING = new Bound("ceiling", "level <= 80", null, Scope.GLOBAL, LEVEL,
            Double.NEGATIVE_INFINITY, 80);
    private static final Scope KITCHEN = new Scope(goTo("kitchen"), goTo("charging_station"));
    private static final Bound SCOPED = new Bound("kitchen", "level >= 20 on the way to the kitchen", null, KITCHEN,
            LEVEL, 20, Double.POSITIVE_INFINITY);

    private static Event goTo(String where) {
        return Event.of(new RecordMatch(RecordKind.COMMAND, "GoTo", "goTo", null, null, List.of(where), null));
    }

    /** A value forecast whose safe training run went no lower than {@code safe} (on the forecast's scale). */
    private static ForecastModel forecast(double limit, double safe) {
        return new ForecastModel(ForecastModel.FORMAT, "s", limit, 1, 0, new Lows(new double[] {safe}, new double[0]),
                1.01, "test", true, Map.of(), List.of(), Calibration.IDENTITY, List.of());
    }

    /** The properties followed as a monitor would, each event kept in a few words (forecasts left out). */
    private static final class Follow {
        final List<String> said = new ArrayList<>();
        final RunState now = new RunState();
        final PropertyFollows follows;

        Follow(List<Property> properties, ForecastModel forecast, WarningRule rule, String headline) {
            FollowContext c = new FollowContext(now, rule, this::said, new Matching(List.of(), 0, 1), headline);
            follows = new PropertyFollows(new ModelSet(null, INDEX, List.of(), forecast), properties, c);
        }

        private void said(MonitorEvent e) {
            if (e instanceof MonitorEvent.Warning w) {
                said.add("warning " + w.clause().id() + " " + w.property() + " " + number(w.value()));
            } else if (e instanceof MonitorEvent.Violation v) {
                said.add("violation " + v.property() + " " + number(v.value()));
            } else if (e instanceof MonitorEvent.Recovered r) {
                said.add("recovered " + r.cause() + " " + r.property() + " " + number(r.value()));
            }
        }

        Follow records(Records r) {
            for (LogRecord x : r.list()) {
                follows.record(x);
            }
            return this;
        }

        Follow levels(double... levels) {
            Records r = new Records();
            for (double v : levels) {
                r.level(v);
            }
            return records(r);
        }
    }

    private static String number(Double v) {
        return v == null || Double.isNaN(v) ? "-" : String.format(Locale.ROOT, "%.1f", v);
    }

    @Test
    void aFloorWarnsBelowTheSafeRunsRecoversPastThemIsViolatedAndHoldsAgain() {
        Follow f = new Follow(List.of(FLOOR), forecast(20, 30), WarningRule.FORECAST, "floor");
        f.levels(50, 45, 29, 28, 29.5, 30.2, 25, 19, 18, 22);
        assertEquals(List.of(
                "warning novelty floor 29.0", // below 30, the safe run's lowest: no nominal model matches
                // 28: still up; 29.5: 9.5 from the floor is past 1.05 * 9 but still below 30, so the cause lasts
                "recovered forecast floor 30.2",
                "warning novelty floor 25.0",
                "violation floor 19.0", // overtakes the warning; 18 is the same violation
                "recovered property floor 22.0",
                "warning novelty floor 22.0"), f.said); // the forecast started over, and 22 is below 30 again
    }

    @Test
    void aCeilingIsAFloorMirrored() {
        ForecastModel top = forecast(20, 30).withBounds(Map.of("ceiling",
                new BoundModel(BoundModel.CEILING, forecast(-80, -70))));
        Follow f = new Follow(List.of(CEILING), top, WarningRule.FORECAST, null);
        f.levels(60, 71, 79, 70.5, 69.9, 81, 79);
        assertEquals(List.of(
                "warning novelty ceiling 71.0", // above 70, the safe run's highest
                // 79 changes nothing; at 70.5 it moved back 9.5 from the ceiling, past 1.05 * 9, but is still above 70
                "recovered forecast ceiling 69.9",
                "violation ceiling 81.0",
                "recovered property ceiling 79.0",
                "warning novelty ceiling 79.0"), f.said);
    }

    @Test
    void aScopedBoundIsJudgedInItsScopeOnlyAndItsAlarmEndsWhenTheScopeCloses() {
        // whatever the rule, with or without a learned forecast: the violation ends with the scope
        for (WarningRule rule : WarningRule.values()) {
            Follow f = new Follow(List.of(SCOPED), null, rule, null);
            f.records(new Records().level(15).goTo("kitchen").level(25).level(18).level(17).goTo("charging_station")
                    .level(12));
            assertEquals(List.of("violation kitchen 18.0", "recovered scope kitchen 17.0"), f.said, rule.toString());
        }
        // a warning still up when the scope closes ends there too; out of the scope 12 warns of nothing
        ForecastModel top = forecast(20, 30).withBounds(Map.of("kitchen",
                new BoundModel(BoundModel.FLOOR, forecast(20, 30))));
        Follow f = new Follow(List.of(SCOPED), top, WarningRule.FORECAST, null);
        f.records(new Records().level(15).goTo("kitchen").level(40).level(28).goTo("charging_station").level(12)
                .goTo("kitchen").level(35));
        assertEquals(List.of("warning novelty kitchen 28.0", "recovered scope kitchen 28.0"), f.said);
    }

    @Test
    void anAlarmStillUpWhenItsRunEndsEnds() {
        Follow f = new Follow(List.of(FLOOR), forecast(20, 30), WarningRule.FORECAST, "floor");
        f.levels(50, 25);
        Records last = new Records().at(9).level(24);
        f.records(last);
        f.follows.runEnded(last.list().get(1), "the run ended");
        f.follows.reset();
        f.levels(50);
        assertEquals(List.of("warning novelty floor 25.0", "recovered run-ended floor 24.0"), f.said);
        f.said.clear();
        f.levels(10);
        f.follows.runEnded(last.list().get(1), "the run ended");
        assertEquals(List.of("violation floor 10.0", "recovered run-ended floor 10.0"), f.said,
                "a violation still up ends with its run too");
    }

    private static final Response NAVIGATION = new Response("navigation-in-time", "a navigation ends in 10 ticks",
            "check whether the robot is stuck", Scope.GLOBAL,
            Event.of(new RecordMatch(RecordKind.COMMAND, "GoTo", "goTo", null, null, null, null)), null,
            Event.of(new RecordMatch(RecordKind.REPLY, "GoTo", "getStatus", null, null, null, List.of("2"))), null,
            new Deadline(10, Deadline.Unit.TICKS, null));

    private long line = 1;

    private LogRecord record(RecordKind kind, String protocol, String command, String reply) {
        LogRecord r = new LogRecord(line, line, "DEBUG", kind, "/a", "/b", protocol, command, "", reply);
        line += 7;
        return r;
    }

    @Test
    void aDeadlineWarnsPastEveryTrainingObligationRecoversWhenDischargedAndIsViolatedWhenMissed() {
        // training navigations took 2, 3, 3 and 4 ticks: pending past 4 ticks is novel, warned at (4 + 10) / 2 = 7
        Survival s = new Survival(new double[] {2, 3, 3, 4}, new double[0]);
        ForecastModel m = new ForecastModel(ForecastModel.FORMAT, "ticks", 20, 4, 0,
                new Lows(new double[] {30}, new double[0]), 0.9, "test", true, Map.of(), List.of(),
                Calibration.IDENTITY, List.of(), Map.of(NAVIGATION.id(), s));
        Follow f = new Follow(List.of(NAVIGATION), m, WarningRule.FORECAST, null);
        f.follows.record(record(RecordKind.COMMAND, "GoTo", "goTo", ""));
        for (int t = 1; t <= 7; t++) {
            f.follows.record(record(RecordKind.TICK, "", "", ""));
        }
        assertEquals(List.of("warning deadline navigation-in-time -"), f.said, "after the 7th tick");
        f.follows.record(record(RecordKind.REPLY, "GoTo", "getStatus", "2"));
        assertEquals("recovered discharged navigation-in-time -", f.said.get(1));
        f.said.clear();
        f.follows.record(record(RecordKind.COMMAND, "GoTo", "goTo", ""));
        for (int t = 1; t <= 11; t++) {
            f.follows.record(record(RecordKind.TICK, "", "", ""));
        }
        f.follows.record(record(RecordKind.REPLY, "GoTo", "getStatus", "2"));
        assertEquals(List.of("warning deadline navigation-in-time -", "violation navigation-in-time -"), f.said,
                "a missed deadline is the property's violation: no recovery until the run ends");
        assertEquals("violated", f.follows.statuses().get(0).verdict().id());
    }
}
