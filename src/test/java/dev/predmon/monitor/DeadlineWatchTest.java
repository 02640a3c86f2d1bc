package dev.predmon.monitor;

import dev.predmon.forecast.Calibration;
import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.Lows;
import dev.predmon.forecast.Survival;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.property.Deadline;
import dev.predmon.property.Event;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.RecordMatch;
import dev.predmon.property.Response;
import dev.predmon.property.Scope;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A navigation that must end within 10 ticks: how long its obligations stay pending is measured, and a pending one
 * is forecast against what training runs took, on hand-made records.
 */
class DeadlineWatchTest {

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

    private LogRecord goTo() {
        return record(RecordKind.COMMAND, "GoTo", "goTo", "");
    }

    private LogRecord arrived() {
        return record(RecordKind.REPLY, "GoTo", "getStatus", "2");
    }

    private LogRecord tick() {
        return record(RecordKind.TICK, "", "", "");
    }

    @Test
    void obligationsAreMeasuredDischargedOrCensored() {
        List<String> seen = new ArrayList<>();
        PropertyChecker c = new PropertyChecker(List.<Property>of(NAVIGATION), (i, p, v) -> { });
        c.onObligations((i, p, d, discharged) -> seen.add((discharged ? "discharged " : "censored ") + d));
        c.accept(goTo());
        c.accept(tick());
        c.accept(tick());
        assertEquals(2.0, c.elapsed(0));
        c.accept(arrived());
        assertTrue(Double.isNaN(c.elapsed(0)), "nothing pending once it arrived");
        c.accept(goTo());
        c.accept(tick());
        c.finish(); // the run ends with the second navigation pending
        c.reset();
        c.accept(goTo());
        for (int t = 0; t < 11; t++) {
            c.accept(tick()); // the 11th tick is past the deadline: violated, and censored there
        }
        assertEquals(List.of("discharged 2.0", "censored 1.0", "censored 11.0"), seen);
    }

    @Test
    void aNavigationPendingPastEveryTrainingOneIsWarnedHalfWayToItsDeadline() {
        // training navigations took 2, 3, 3 and 4 ticks
        Survival s = new Survival(new double[] {2, 3, 3, 4}, new double[0]);
        PropertyChecker c = new PropertyChecker(List.<Property>of(NAVIGATION), (i, p, v) -> { });
        DeadlineWatch w = new DeadlineWatch(List.of(NAVIGATION), model(s));
        List<DeadlineWatch.Due> due = new ArrayList<>();
        c.accept(goTo());
        int warnedAt = -1;
        for (int t = 1; t <= 10 && warnedAt < 0; t++) {
            c.accept(tick());
            w.step(c, null, told(due));
            warnedAt = due.isEmpty() ? -1 : t;
        }
        assertEquals(7, warnedAt, "(4 + 10) / 2: past the longest training navigation, half way to the deadline");
        DeadlineWatch.Due d = due.get(0);
        assertTrue(d.estimate().novel());
        assertEquals(3.0, d.estimate().timeLeft());
        assertTrue(d.reason().contains("longer than any of the 4 training obligations"), d.reason());
        for (int t = 0; t < 2; t++) {
            c.accept(tick());
            w.step(c, null, told(due));
        }
        assertEquals(1, due.size(), "once per obligation");
    }

    @Test
    void aNavigationAsLongAsTrainingOnesIsNotWarnedAndNoTrainingMeansNoVerdict() {
        Survival s = new Survival(new double[] {2, 3, 3, 4}, new double[0]);
        PropertyChecker c = new PropertyChecker(List.<Property>of(NAVIGATION), (i, p, v) -> { });
        DeadlineWatch w = new DeadlineWatch(List.of(NAVIGATION), model(s));
        DeadlineWatch none = new DeadlineWatch(List.of(NAVIGATION), model(new Survival(new double[0], new double[0])));
        List<DeadlineWatch.Due> due = new ArrayList<>();
        c.accept(goTo());
        for (int t = 0; t < 4; t++) {
            c.accept(tick());
            w.step(c, null, told(due));
            none.step(c, null, told(due));
        }
        c.accept(arrived());
        w.step(c, null, told(due));
        assertTrue(due.isEmpty(), due.toString());
    }

    /** Tells {@code due} the warnings only. */
    private static DeadlineWatch.Listener told(List<DeadlineWatch.Due> due) {
        return new Told() {
            @Override
            public void due(LogRecord r, DeadlineWatch.Due d) {
                due.add(d);
            }
        };
    }

    /** What a deadline watch told, in a few words each. */
    private static class Told implements DeadlineWatch.Listener {
        final List<String> said = new ArrayList<>();

        @Override
        public void due(LogRecord r, DeadlineWatch.Due d) {
            said.add("warning " + (d.estimate().novel() ? "novel" : DeadlineWatch.shown(d.estimate())));
        }

        @Override
        public void recovered(LogRecord r, Response p, String reason) {
            said.add("recovered " + p.id() + " at line " + r.line());
        }

        @Override
        public void changed(LogRecord r, Response p, Survival.Estimate e) {
            said.add("forecast " + DeadlineWatch.shown(e) + " " + e.timeLeft());
        }
    }

    /** A checker of the navigation whose obligations' ends {@code w} hears, as the safety monitor wires them. */
    private static PropertyChecker checker(DeadlineWatch w) {
        PropertyChecker c = new PropertyChecker(List.<Property>of(NAVIGATION), (i, p, v) -> { });
        c.onObligations((i, p, d, discharged) -> w.closed(i, d, discharged));
        return c;
    }

    private void step(PropertyChecker c, DeadlineWatch w, LogRecord r, Told told) {
        c.accept(r);
        w.step(c, r, told);
    }

    @Test
    void aWarnedNavigationThatArrivesInTimeRecoversAndOneThatMissesStaysWithoutRecovery() {
        // training navigations took 2, 3, 3 and 4 ticks: pending past 4 ticks is novel, warned at (4 + 10) / 2 = 7
        Survival s = new Survival(new double[] {2, 3, 3, 4}, new double[0]);
        DeadlineWatch w = new DeadlineWatch(List.of(NAVIGATION), model(s));
        PropertyChecker c = checker(w);
        Told told = new Told();
        step(c, w, goTo(), told);
        for (int t = 0; t < 7; t++) {
            step(c, w, tick(), told);
        }
        assertTrue(w.warned(0));
        LogRecord arrived = arrived();
        step(c, w, arrived, told);
        assertEquals(List.of(
                // P(miss) = S(10) / S(t) shrunk towards S(10) = 0: every training one took 4 ticks or less; told once
                // while it reads 0% (10 ticks left at the goTo)
                "forecast 0% 10.0",
                // after 4 ticks no training navigation was still pending (the longest took 4): no evidence, 6 left
                "forecast novel 5.0",
                "warning novel",
                "recovered navigation-in-time at line " + arrived.line()), told.said);
        assertTrue(Double.isNaN(c.elapsed(0)) && !w.warned(0) && w.current(0) == null, "the alarm is over");

        told.said.clear();
        step(c, w, goTo(), told);
        for (int t = 0; t < 11; t++) {
            step(c, w, tick(), told);
        }
        step(c, w, arrived(), told);
        assertEquals(List.of("forecast 0% 10.0", "forecast novel 5.0", "warning novel"), told.said,
                "a missed deadline is the property's violation: no recovery");
    }

    /**
     * Training navigations took 2, 3, 3 and 4 ticks, and two were still pending at 12 (censored), so S(10) = 1/3:
     * with the prior of 2 runs, P(miss) is (6 * 1/3 + 2/3) / 8 = 1/3 at first, (3 * 2/3 + 2/3) / 5 = 0.53 after
     * tick 3 and (2 * 1 + 2/3) / 4 = 0.67 after tick 4. The default rule warns at even odds (tick 3); a learned
     * threshold of 0.6 waits for tick 4; one of 0.7 never warns (never past every training navigation), unless the
     * calibration lifts the estimate: then it warns at tick 3, with the calibrated probability.
     */
    @Test
    void itWarnsAtTheLearnedThresholdOnTheCalibratedScale() {
        Survival s = new Survival(new double[] {2, 3, 3, 4}, new double[] {12, 12});
        assertEquals(3, warnedAt(model(s)).tick());
        Warned at06 = warnedAt(model(s, new DeadlineRule(0.6, "learned", true, Calibration.IDENTITY)));
        assertEquals(4, at06.tick());
        assertEquals(2.0 / 3, at06.due().estimate().probability(), 1e-12);
        assertEquals(-1, warnedAt(model(s, new DeadlineRule(0.7, "learned", true, Calibration.IDENTITY))).tick());
        Calibration lift = new Calibration(1, 1, 5);
        Warned lifted = warnedAt(model(s, new DeadlineRule(0.7, "learned", true, lift)));
        assertEquals(3, lifted.tick());
        assertEquals(lift.apply(8.0 / 15), lifted.due().estimate().probability(), 1e-12);
        assertTrue(lifted.due().reason().contains("P(miss) 0.76"), lifted.due().reason());
    }

    private record Warned(int tick, DeadlineWatch.Due due) {
    }

    /** When a navigation that never arrives is first warned, in ticks (-1 when not before its deadline). */
    private Warned warnedAt(ForecastModel model) {
        PropertyChecker c = new PropertyChecker(List.<Property>of(NAVIGATION), (i, p, v) -> { });
        DeadlineWatch w = new DeadlineWatch(List.of(NAVIGATION), model);
        List<DeadlineWatch.Due> due = new ArrayList<>();
        c.accept(goTo());
        w.step(c, null, told(due));
        for (int t = 1; t <= 10; t++) {
            c.accept(tick());
            w.step(c, null, told(due));
            if (!due.isEmpty()) {
                return new Warned(t, due.get(0));
            }
        }
        return new Warned(-1, null);
    }

    private static ForecastModel model(Survival s, DeadlineRule rule) {
        return new ForecastModel(ForecastModel.FORMAT, "ticks", 20, 4, 0, new Lows(new double[] {30}, new double[0]),
                0.9, "test", true, Map.of(), List.of(), Calibration.IDENTITY, List.of(), Map.of(NAVIGATION.id(), s),
                Map.of(NAVIGATION.id(), rule));
    }

    private static ForecastModel model(Survival s) {
        return new ForecastModel(ForecastModel.FORMAT, "ticks", 20, 4, 0, new Lows(new double[] {30}, new double[0]),
                0.9, "test", true, Map.of(), List.of(), Calibration.IDENTITY, List.of(), Map.of(NAVIGATION.id(), s));
    }
}
