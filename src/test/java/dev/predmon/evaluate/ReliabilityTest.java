package dev.predmon.evaluate;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

/** The Brier score, its base-rate baseline, the calibration error and the reliability table, checked by hand. */
class ReliabilityTest {

    private static final double EPS = 1e-12;

    /**
     * Run A: 0.2 (outcome 0) and 0.6 (outcome 1), each half the run's weight; run B: 0.9 (outcome 1). Base rate 0.25.
     * Brier: A = 0.5 * 0.04 + 0.5 * 0.16 = 0.10, B = 0.01, mean 0.055. Base: A = 0.5 * 0.0625 + 0.5 * 0.5625 =
     * 0.3125, B = 0.5625, mean 0.4375. Bins 0.2, 0.6, 0.9 with weights 0.5, 0.5, 1: ECE = (0.5 * 0.2 + 0.5 * 0.4 +
     * 1 * 0.1) / 2 = 0.2.
     */
    @Test
    void scoresEachForecastAgainstItsOwnOutcomeWithRunsWeighingTheSame() {
        Reliability r = Reliability.of(List.of(
                new Reliability.Run(List.of(0.2, 0.6), List.of(0, 1), 0.25),
                new Reliability.Run(List.of(0.9), List.of(1), 0.25),
                new Reliability.Run(List.of(), List.of(), 0.25)));
        assertEquals(2, r.runs(), "a run without a forecast is left out");
        assertEquals(3, r.forecasts());
        assertEquals(2, r.violating());
        assertEquals(0.055, r.brier(), EPS);
        assertEquals(0.4375, r.baseBrier(), EPS);
        assertEquals(0.2, r.ece(), EPS);
        assertEquals(3, r.bins().size(), "only the bins with a forecast");
        Reliability.Bin six = r.bins().get(1);
        assertEquals(0.6, six.from(), EPS);
        assertEquals(0.7, six.to(), EPS);
        assertEquals(0.5, six.weight(), EPS);
        assertEquals(1, six.forecasts());
        assertEquals(0.6, six.predicted(), EPS);
        assertEquals(1.0, six.observed(), EPS);
        assertEquals(0.0, r.bins().get(0).observed(), EPS);
    }

    /** A run whose every forecast has the run's outcome: its base rate is scored once, as the battery's always was. */
    @Test
    void aRunsOutcomeIsEveryForecastsOutcome() {
        Reliability r = Reliability.of(List.of(Reliability.Run.of(List.of(0.3, 0.5), true, 0.4),
                Reliability.Run.of(List.of(0.1), false, 0.4)));
        // (0.5 * 0.49 + 0.5 * 0.25 + 0.01) / 2 and ((0.6^2) + (0.4^2)) / 2
        assertEquals(0.19, r.brier(), EPS);
        assertEquals(0.26, r.baseBrier(), EPS);
        assertEquals(1, r.violating());
    }

    @Test
    void withoutABaseRateThereIsNoBaseline() {
        Reliability r = Reliability.of(List.of(Reliability.Run.of(List.of(0.3), true, 0.4),
                Reliability.Run.of(List.of(0.1), false, null)));
        assertNull(r.baseBrier());
        assertEquals((0.49 + 0.01) / 2, r.brier(), EPS);
    }

    @Test
    void noForecastIsNoScore() {
        assertNull(Reliability.of(List.of()));
        assertNull(Reliability.of(List.of(Reliability.Run.of(List.of(), true, 0.5))));
    }
}
