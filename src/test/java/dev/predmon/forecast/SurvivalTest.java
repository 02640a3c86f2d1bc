package dev.predmon.forecast;

import dev.predmon.pipeline.TriggerInputs;
import org.junit.jupiter.api.Test;

import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Kaplan-Meier on a hand-computed sample: discharged after 2, 4, 4, 6; censored at 3 and 5. */
class SurvivalTest {

    private final Survival s = new Survival(new double[] {4, 2, 6, 4}, new double[] {5, 3});

    @Test
    void survivalStepsAtEachDischargeWithCensoredRunsAtRiskUntilTheirTime() {
        assertEquals(1.0, s.survival(1.9), 1e-12);
        assertEquals(5.0 / 6, s.survival(2), 1e-12); // 6 at risk, 1 discharged
        assertEquals(5.0 / 6, s.survival(3.5), 1e-12);
        assertEquals(5.0 / 12, s.survival(4), 1e-12); // at risk: 4, 4, 6 and the one censored at 5
        assertEquals(0.0, s.survival(6), 1e-12);
        assertEquals(6, s.size());
        assertEquals(6.0, s.longest());
    }

    @Test
    void aPendingObligationIsJudgedOnTheRunsStillPendingThatLongShrunkTowardsTheOverallMissRate() {
        Survival.Estimate e = s.estimate(3, 5);
        // S(5) / S(3) = 0.5 over 4 runs at risk; the prior: 2 runs at the miss rate (6 S(5) + 1/2) / 7 = 3/7
        assertEquals((4 * 0.5 + 2 * 3.0 / 7) / 6, e.probability(), 1e-12);
        assertEquals(2.0, e.timeLeft());
        assertEquals(4, e.atRisk());
        assertEquals(1, e.longer()); // only the run discharged at 6 is known to have been pending past 5
        assertFalse(e.novel());
    }

    @Test
    void pastEveryTrainingObligationTheEstimateSaysItHasNoEvidence() {
        Survival.Estimate e = s.estimate(6.5, 10);
        assertTrue(e.novel());
        assertTrue(Double.isNaN(e.probability()));
        assertEquals(3.5, e.timeLeft());
        assertTrue(new Survival(new double[0], new double[0]).estimate(0, 10).novel());
    }

    @Test
    void pendingExactlyAsLongAsTheLongestIsNotYetNovel() {
        // Every grasp of training held at its first attempt: a grasp at its first attempt, its reply still to come,
        // is what every training grasp was too; only a second attempt is longer than any of them.
        Survival grasps = new Survival(new double[] {1, 1, 1}, new double[0]);
        assertFalse(grasps.estimate(1, 8).novel());
        // none of 3 missed: about once in 8, not never ((3 * 0 + 1/2) / 4)
        assertEquals(0.125, grasps.estimate(1, 8).probability(), 1e-12);
        assertTrue(grasps.estimate(2, 8).novel());
        assertFalse(s.estimate(6, 10).novel(), "the longest training obligation took 6");
    }

    @Test
    void runsThatEndedEarlyDoNotReadAsFast() {
        // Five obligations censored at 1 (the runs stopped) and one discharged at 10: the naive share of "discharged
        // by 5" over all six would be 0; Kaplan-Meier keeps the one run that was watched long enough.
        Survival early = new Survival(new double[] {10}, new double[] {1, 1, 1, 1, 1});
        assertEquals(1.0, early.survival(5), 1e-12);
        assertEquals(0.0, early.survival(10), 1e-12);
        assertEquals(1, early.estimate(5, 8).atRisk());
    }

    @Test
    void negativeOrNonFiniteDurationsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new Survival(new double[] {-1}, new double[0]));
        assertThrows(IllegalArgumentException.class, () -> new Survival(new double[0], new double[] {Double.NaN}));
    }

    /** {@code n} durations whose {@code log(1 + d)} is {@code x}. */
    private static double[] logs(int n, double x) {
        double[] d = new double[n];
        java.util.Arrays.fill(d, Math.expm1(x));
        return d;
    }

    private static double[] join(double[]... parts) {
        return java.util.Arrays.stream(parts).flatMapToDouble(java.util.Arrays::stream).toArray();
    }

    /**
     * Short legs: ten whose {@code log(1 + d)} is 1 (five) and 2 (five): mean 1.5, variance 10 * 0.25 / 9 = 0.2778.
     * The property's twenty: those and ten long ones at 3 and 4: mean 2.5, variance 25 / 19 = 1.3158. Pooled with the
     * weight of two obligations: mu = (10 * 1.5 + 2 * 2.5) / 12 = 1.6667, s2 = (9 * 0.2778 + 2 * 1.3158) / 11 =
     * 0.46651 on 11 degrees of freedom; t(0.99; 11) = 2.71808 (the tables' 2.718), so the bound is
     * exp(1.6667 + 2.71808 * sqrt(0.46651 * 13 / 12)) - 1 = exp(3.59896) - 1 = 35.56: a short leg is late after 35.56
     * ticks, where the long ones took up to e^4 - 1 = 53.6. At 99.9% (t = 4.02470) the bound, 91.56, is past every
     * leg of the property: it is capped there, at 53.6.
     */
    @Test
    void aShortLegIsLateAtItsOwnPredictionBoundPooledTowardsTheProperty() {
        double[] shortLegs = join(logs(5, 1), logs(5, 2));
        double[] longLegs = join(logs(5, 3), logs(5, 4));
        Survival pooled = new Survival(join(shortLegs, longLegs), new double[0]).withContexts(Map.of(
                "goTo_ch_i", new Survival(shortLegs, new double[0]),
                "goTo_ki_i", new Survival(longLegs, new double[0])));
        Survival station = pooled.at("start" + TriggerInputs.AFTER + "goTo_ch_i");
        assertEquals(35.56007, station.lateAfter(0.99), 1e-4);
        assertEquals(Math.expm1(4), station.lateAfter(0.999), 1e-9);
        assertFalse(DeadlineRule.pastLate(35, station, 0.99));
        assertTrue(DeadlineRule.pastLate(36, station, 0.99));
        // the property's own curve: mean 2.5, variance 1.3158 on 19 degrees of freedom, t(0.99; 19) = 2.53948:
        // exp(2.5 + 2.53948 * sqrt(1.3158 * 21 / 20)) - 1 = exp(5.48498) - 1, past every leg: capped at 53.6
        assertEquals(Math.expm1(4), pooled.lateAfter(0.99), 1e-9);
        assertEquals(Math.expm1(4), pooled.at("nowhere").lateAfter(0.99), 1e-9);
    }

    /**
     * Censored obligations (a run that ended on the way) do not enter the fit: they tell how long a response was waited
     * for, not how long it took. A leg that outlasted its bound is never late before it, however: the bound is at
     * least the longest leg of its condition. Without two discharged legs there is no fit.
     */
    @Test
    void theLateBoundIgnoresCensoredLegsAndIsNeverBeforeTheLongestLeg() {
        double[] shortLegs = join(logs(5, 1), logs(5, 2));
        Survival alone = new Survival(shortLegs, new double[0]);
        Survival waited = new Survival(shortLegs, new double[] {300, 333});
        assertEquals(alone.lateAfter(0.99), waited.lateAfter(0.99), 1e-12);
        // ten legs at log 1 and one at log 3: mean 1.1818, sd 0.6030 on 10 degrees of freedom, t(0.99; 10) = 2.76377:
        // exp(1.1818 + 2.76377 * 0.6030 * sqrt(12 / 11)) - 1 = exp(2.9225) - 1 = 17.59, below the leg of e^3 - 1 = 19.09
        Survival outlier = new Survival(join(logs(10, 1), logs(1, 3)), new double[0]);
        assertEquals(Math.expm1(3), outlier.lateAfter(0.99), 1e-9);
        assertTrue(Double.isNaN(new Survival(new double[] {4}, new double[] {50}).lateAfter(0.99)));
        assertThrows(IllegalArgumentException.class, () -> alone.lateAfter(0.5));
    }
}
