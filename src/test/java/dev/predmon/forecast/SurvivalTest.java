package dev.predmon.forecast;

import org.junit.jupiter.api.Test;

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
}
