package dev.predmon.learn;

import dev.predmon.forecast.CrossValidation;
import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.Scorecard;
import dev.predmon.forecast.Survival;
import dev.predmon.parse.RecordKind;
import dev.predmon.property.Deadline;
import dev.predmon.property.Event;
import dev.predmon.property.RecordMatch;
import dev.predmon.property.Response;
import dev.predmon.property.Scope;
import dev.predmon.replay.ReplayedRun;
import dev.predmon.replay.ReplayedRun.Obligation;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;
import java.util.stream.IntStream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The deadline rule chosen by cross-validation on a handful of held-out navigations with a deadline of 10 ticks, as
 * the replay of their logs forecast them; their forecasts are worked out by hand below.
 */
class DeadlineTrainingTest {

    private static final String ID = "navigation-in-time";
    private static final Response NAVIGATION = new Response(ID, "a navigation ends in 10 ticks", null, Scope.GLOBAL,
            Event.of(new RecordMatch(RecordKind.COMMAND, "GoTo", "goTo", null, null, null, null)), null,
            Event.of(new RecordMatch(RecordKind.REPLY, "GoTo", "getStatus", null, null, null, List.of("2"))), null,
            new Deadline(10, Deadline.Unit.TICKS, null));

    /**
     * Two logs, two folds. Each log holds a navigation that arrived after 2 ticks (forecast at ticks 0 and 1) and
     * one that was still pending at tick 11, past its deadline (forecast at ticks 0 to 10). Each fold's training
     * obligations are then the other log's: discharged at 2, censored at 11, so S(10) = 1/2 and, with the prior of 2
     * runs at that base rate, P(miss) = (2 * 1/2 + 2 * 1/2) / 4 = 0.5 while both are pending (ticks 0 and 1) and
     * (1 * 1 + 2 * 1/2) / 3 = 2/3 once only the censored one is (ticks 2 to 10). The navigations that arrived peak
     * at 0.5, those that missed at 2/3: a threshold between them, on the calibrated scale, makes no wrong call.
     */
    @Test
    void heldOutNavigationsChooseAThresholdBetweenTheArrivedAndTheMissedOnes() {
        HeldOutFolds folds = twoFolds(List.of(arrived(2), missed()), List.of(arrived(2), missed()));
        List<DeadlineTraining.HeldOut> judged = DeadlineTraining.heldOut(ID, folds);
        assertEquals(4, judged.size());
        for (DeadlineTraining.HeldOut h : judged) {
            assertEquals(h.missed() ? 2.0 / 3 : 0.5, h.peak(), 1e-12, h.toString());
            assertEquals(0.5, h.baseRate(), 1e-12);
            assertTrue(Double.isNaN(h.caughtAt()), "never past every training obligation: censored at 11");
        }
        CrossValidation.Choice choice = choose(folds);
        DeadlineRule rule = DeadlineTraining.rule(choice);
        assertTrue(rule.validated(), rule.note());
        assertTrue(rule.note().contains("on 4 held-out obligations: warned 2 of 2 violations, 0 false alarm(s) in 2"),
                rule.note());
        double met = rule.calibration().apply(0.5);
        double miss = rule.calibration().apply(2.0 / 3);
        assertTrue(met < rule.threshold() && rule.threshold() <= miss, met + " < " + rule.threshold() + " <= " + miss);
        assertTrue(rule.threshold() >= 0.5, "never below even odds");

        Scorecard card = choice.scorecard();
        assertEquals(Scorecard.OBLIGATIONS, card.counted());
        assertEquals(List.of(4, 2, 2, 0), List.of(card.runs(), card.violating(), card.warned(), card.falseAlarms()));
        assertEquals("ticks", card.unit());
        // the elapsed-time baseline never warns: no navigation is pending past the one censored at 11
        assertEquals(List.of(4, 2, 0, 0), List.of(card.baseline().runs(), card.baseline().violating(),
                card.baseline().warned(), card.baseline().falseAlarms()));
        assertFalse(card.baselineChosen());
        assertFalse(rule.baseline());
    }

    /** Without a missed deadline among the held-out navigations there is nothing to choose: the default, unvalidated. */
    @Test
    void noMissMeansTheDefaultRuleAndSaysSo() {
        DeadlineRule rule = DeadlineTraining.rule(choose(
                twoFolds(List.of(arrived(2), arrived(3)), List.of(arrived(4), arrived(2)))));
        assertFalse(rule.validated());
        // no held-out miss checked any probability: it is shown, and warns at none
        assertEquals(DeadlineRule.NEVER, rule.threshold());
        assertEquals(DeadlineRule.DEFAULT.calibration(), rule.calibration());
        assertTrue(rule.note().contains("not validated: the probability is shown but does not warn"), rule.note());
        Survival even = new Survival(new double[] {2, 3}, new double[] {1, 1});
        assertFalse(rule.warns(even.estimate(1, 10), 1, 10, even), "even odds from obligations cut short warn not");
        // with no false alarm by any clause, the earliest: the late clause at 99%, which for these three legs (2, 3
        // and 4 ticks; a bound far past them with two degrees of freedom) is capped at the longest of them
        assertEquals(0.99, rule.level());
        Survival s = new Survival(new double[] {2, 3, 4}, new double[0]);
        assertFalse(rule.warns(s.estimate(4, 10), 4, 10, s));
        assertTrue(rule.warns(s.estimate(5, 10), 5, 10, s));
    }

    /**
     * A fold trained on navigations that arrived after 2 and 3 ticks: one stuck for good is past every one of them
     * from tick 4, so the novelty clause warns it there at no margin, and at 4 + (10 - 4) / 2 = 7 with half of it; the
     * elapsed-time baseline warns it at 4 too. One arriving after 5 ticks is warned at 4 by both: a false alarm. The
     * late clause at either level is capped at the longest leg, 3 ticks (the bound of a log-normal fitted to two legs,
     * with one degree of freedom, is far past it), and warns both at 4 as well; without the curve it was judged
     * against, an obligation gets no late clause.
     */
    @Test
    void theNoveltyClauseAtEachMarginAndTheBaselineAsHandWorked() {
        Survival shortLegs = new Survival(new double[] {2, 3}, new double[0]);
        Obligation stuck = new Obligation(NAVIGATION, steps(11, shortLegs), 11, false, 11, 11, Double.NaN,
                shortLegs);
        Obligation slow = new Obligation(NAVIGATION, steps(5, shortLegs), 5, true, 5, 5, Double.NaN, shortLegs);
        HeldOutFolds folds = new HeldOutFolds(2, List.of(
                new HeldOutFolds.Fold(0, 0.5, Map.of(ID, shortLegs), true, List.of(run(List.of(stuck)))),
                new HeldOutFolds.Fold(1, 0.5, Map.of(ID, shortLegs), true, List.of(run(List.of(slow))))));
        List<CrossValidation.Case> cases = DeadlineTraining.cases(ID, folds);
        assertEquals(List.of(4.0, 4.0, 4.0, 4.0, 4.0, 7.0), cases.get(0).variants());
        assertEquals(4.0, cases.get(0).baselineAt());
        assertEquals(List.of(4.0, 4.0, 4.0, 4.0, 4.0, Double.NaN), cases.get(1).variants());
        assertEquals(4.0, cases.get(1).baselineAt());
        Obligation unknown = new Obligation(NAVIGATION, steps(11, shortLegs), 11, false, 11, 11, Double.NaN);
        assertEquals(List.of(Double.NaN, Double.NaN, Double.NaN, Double.NaN, 4.0, 7.0), DeadlineTraining.cases(ID, new HeldOutFolds(2,
                List.of(new HeldOutFolds.Fold(0, 0.5, Map.of(ID, shortLegs), true, List.of(run(List.of(unknown)))))))
                .get(0).variants());
    }

    /**
     * A navigation let go before its deadline (its scope closed) has no known outcome and is not judged; one whose
     * fold has no training obligation has no forecast and is not judged either.
     */
    @Test
    void aNavigationLetGoBeforeItsDeadlineIsNotJudged() {
        Obligation ended = new Obligation(NAVIGATION, steps(5, TRAINING), 5, false, 5, 5, Double.NaN);
        assertEquals(3, DeadlineTraining.cases(ID, twoFolds(List.of(arrived(2), ended),
                List.of(arrived(2), missed()))).size());
        HeldOutFolds untrained = new HeldOutFolds(2, List.of(fold(0, List.of(arrived(2))),
                new HeldOutFolds.Fold(1, 0.5, Map.of(), true, List.of(run(List.of(missed()))))));
        assertEquals(1, DeadlineTraining.cases(ID, untrained).size());
    }

    /** The novelty clause's warning, as the replay tells it, is the obligation's catch whatever the threshold. */
    @Test
    void anObligationTheNoveltyClauseWarnedIsCaughtWhereItWarned() {
        Obligation stuck = new Obligation(NAVIGATION, steps(11, TRAINING), 11, false, 11, 11, 7);
        List<DeadlineTraining.HeldOut> judged = DeadlineTraining.heldOut(ID,
                twoFolds(List.of(arrived(2), stuck), List.of(arrived(2), missed())));
        assertEquals(List.of(Double.NaN, 7.0, Double.NaN, Double.NaN),
                judged.stream().map(DeadlineTraining.HeldOut::caughtAt).toList());
    }

    private static CrossValidation.Choice choose(HeldOutFolds folds) {
        return CrossValidation.choose(DeadlineTraining.cases(ID, folds), 2, new CrossValidation.Space(
                DeadlineRule.variants(), 0, Scorecard.OBLIGATIONS), new Scorecard.Names(NAVIGATION.name(),
                "ticks", Scorecard.OBLIGATIONS, Scorecard.FORECAST, Scorecard.ELAPSED));
    }

    /** Each fold's training obligations: one discharged at 2 ticks, one censored at 11. */
    private static final Survival TRAINING = new Survival(new double[] {2}, new double[] {11});

    /** Two folds, each holding out one log's navigations, each trained on the other's ({@link #TRAINING}). */
    private static HeldOutFolds twoFolds(List<Obligation> a, List<Obligation> b) {
        return new HeldOutFolds(2, List.of(fold(0, a), fold(1, b)));
    }

    private static HeldOutFolds.Fold fold(int index, List<Obligation> held) {
        return new HeldOutFolds.Fold(index, 0.5, Map.of(ID, TRAINING), true, List.of(run(held)));
    }

    private static HeldOutRun run(List<Obligation> obligations) {
        return new HeldOutRun(false, List.of(), List.of(), Double.NaN, Double.NaN, obligations);
    }

    private static Obligation arrived(int ticks) {
        return new Obligation(NAVIGATION, steps(ticks, TRAINING), ticks, true, ticks, ticks, Double.NaN);
    }

    private static Obligation missed() {
        return new Obligation(NAVIGATION, steps(11, TRAINING), 11, false, 11, 11, Double.NaN);
    }

    /**
     * The forecasts of an obligation judged at ticks 0 to {@code duration - 1}, as the monitor makes them from
     * {@code survival}: closed at the record of tick {@code duration}.
     */
    private static List<ReplayedRun.Step> steps(int duration, Survival survival) {
        return IntStream.range(0, duration).mapToObj(t -> new ReplayedRun.Step(survival.estimate(t, 10), t, t, t))
                .toList();
    }
}
