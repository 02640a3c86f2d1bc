package dev.predmon.learn;

import dev.predmon.compact.IoPair;
import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.Scorecard;
import dev.predmon.forecast.Survival;
import dev.predmon.parse.RecordKind;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import dev.predmon.property.Deadline;
import dev.predmon.property.Event;
import dev.predmon.property.RecordMatch;
import dev.predmon.property.Response;
import dev.predmon.property.Scope;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.IntStream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The deadline rule chosen by cross-validation on a handful of navigations with a deadline of 10 ticks, whose
 * forecasts are worked out by hand below.
 */
class DeadlineTrainingTest {

    private static final String ID = "navigation-in-time";
    private static final Response NAVIGATION = new Response(ID, "a navigation ends in 10 ticks", null, Scope.GLOBAL,
            Event.of(new RecordMatch(RecordKind.COMMAND, "GoTo", "goTo", null, null, null, null)), null,
            Event.of(new RecordMatch(RecordKind.REPLY, "GoTo", "getStatus", null, null, null, List.of("2"))), null,
            new Deadline(10, Deadline.Unit.TICKS, null));

    /**
     * Two logs, two folds. Each log holds a navigation that arrived after 2 ticks (forecast after ticks 0 and 1) and
     * one that was still pending at tick 11, past its deadline (forecast after ticks 0 to 10). Each fold's training
     * obligations are then the other log's: discharged at 2, censored at 11, so S(10) = 1/2 and, with the prior of 2
     * runs at that base rate, P(miss) = (2 * 1/2 + 2 * 1/2) / 4 = 0.5 while both are pending (ticks 0 and 1) and
     * (1 * 1 + 2 * 1/2) / 3 = 2/3 once only the censored one is (ticks 2 to 10). The navigations that arrived peak
     * at 0.5, those that missed at 2/3: a threshold between them, on the calibrated scale, makes no wrong call.
     */
    @Test
    void heldOutNavigationsChooseAThresholdBetweenTheArrivedAndTheMissedOnes() {
        List<ScenarioSpec> specs = List.of(spec(Path.of("a.log"), Path.of("b.log")));
        Map<Path, LogTrace> traces = Map.of(Path.of("a.log"), log("a.log", arrived(2), missed()),
                Path.of("b.log"), log("b.log", arrived(2), missed()));
        Map<Path, Integer> folds = ForecastTraining.folds(ForecastTraining.present(specs, traces));
        assertEquals(Map.of(Path.of("a.log"), 0, Path.of("b.log"), 1), folds);
        List<DeadlineTraining.HeldOut> judged = DeadlineTraining.heldOut(ID, specs, traces, folds, 2);
        assertEquals(4, judged.size());
        for (DeadlineTraining.HeldOut h : judged) {
            assertEquals(h.missed() ? 2.0 / 3 : 0.5, h.peak(), 1e-12, h.toString());
            assertEquals(0.5, h.baseRate(), 1e-12);
            assertTrue(Double.isNaN(h.caughtAt()), "never past every training obligation: censored at 11");
        }
        DeadlineRule rule = DeadlineTraining.rule(judged);
        assertTrue(rule.validated(), rule.note());
        assertTrue(rule.note().contains("on 4 held-out obligations: warned 2 of 2 violations, 0 false alarm(s) in 2"),
                rule.note());
        double met = rule.calibration().apply(0.5);
        double miss = rule.calibration().apply(2.0 / 3);
        assertTrue(met < rule.threshold() && rule.threshold() <= miss, met + " < " + rule.threshold() + " <= " + miss);
        assertTrue(rule.threshold() >= 0.5, "never below even odds");

        Scorecard card = DeadlineTraining.scorecard(NAVIGATION, 2, judged);
        assertEquals(Scorecard.OBLIGATIONS, card.counted());
        assertEquals(List.of(4, 2, 0), List.of(card.runs(), card.violating(), card.falseAlarms()));
        assertEquals("ticks", card.unit());
    }

    /** Without a missed deadline among the held-out navigations there is nothing to choose: the default, unvalidated. */
    @Test
    void noMissMeansTheDefaultRuleAndSaysSo() {
        List<ScenarioSpec> specs = List.of(spec(Path.of("a.log"), Path.of("b.log")));
        Map<Path, LogTrace> traces = Map.of(Path.of("a.log"), log("a.log", arrived(2), arrived(3)),
                Path.of("b.log"), log("b.log", arrived(4), arrived(2)));
        DeadlineRule rule = DeadlineTraining.rule(DeadlineTraining.heldOut(ID, specs, traces,
                ForecastTraining.folds(ForecastTraining.present(specs, traces)), 2));
        assertFalse(rule.validated());
        assertEquals(0.5, rule.threshold());
        assertEquals(DeadlineRule.DEFAULT.calibration(), rule.calibration());
        assertTrue(rule.note().startsWith("default 0.50: the 4 held-out obligations all held; not validated"),
                rule.note());
        // and the default rule still warns a navigation pending past every training one, half way to its deadline
        Survival s = new Survival(new double[] {2, 3, 4}, new double[0]);
        assertFalse(rule.warns(s.estimate(6.9, 10), 6.9, 10, s));
        assertTrue(rule.warns(s.estimate(7, 10), 7, 10, s));
    }

    /** A navigation censored before its deadline (its run ended) has no known outcome and is not judged. */
    @Test
    void aNavigationLetGoBeforeItsDeadlineIsNotJudged() {
        List<ScenarioSpec> specs = List.of(spec(Path.of("a.log"), Path.of("b.log")));
        RunTiming.Obligation ended = new RunTiming.Obligation(ID, 5, false, 10, steps(5));
        Map<Path, LogTrace> traces = Map.of(Path.of("a.log"), log("a.log", arrived(2), ended),
                Path.of("b.log"), log("b.log", arrived(2), missed()));
        assertEquals(3, DeadlineTraining.heldOut(ID, specs, traces, ForecastTraining.folds(ForecastTraining.present(specs, traces)), 2).size());
    }

    private static ScenarioSpec spec(Path... logs) {
        return new ScenarioSpec("runs", false, "", List.of(logs));
    }

    private static RunTiming.Obligation arrived(int ticks) {
        return new RunTiming.Obligation(ID, ticks, true, 10, steps(ticks));
    }

    private static RunTiming.Obligation missed() {
        return new RunTiming.Obligation(ID, 11, false, 10, steps(11));
    }

    /** Pending after the records at ticks 0 to {@code duration - 1}: closed at the record of tick {@code duration}. */
    private static double[] steps(int duration) {
        return IntStream.range(0, duration).asDoubleStream().toArray();
    }

    private static LogTrace log(String name, RunTiming.Obligation... obligations) {
        List<IoPair> pairs = List.of(new IoPair("goTo", "ok", null, null));
        RunTiming timing = new RunTiming(new double[] {0}, new double[] {Double.NaN}, Double.NaN, 20, Double.NaN,
                "ticks", List.of(), List.of(), List.of(obligations));
        List<LogTrace.Run> runs = new ArrayList<>();
        runs.add(new LogTrace.Run(0, 1, pairs, false, Map.of(), timing));
        return new LogTrace(Path.of(name), pairs, List.of(), 1, 1, 1, Map.of(), runs, 1);
    }
}
