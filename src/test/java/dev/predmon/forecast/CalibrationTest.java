package dev.predmon.forecast;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.DoubleUnaryOperator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

class CalibrationTest {

    /** Runs whose true chance of violating is {@code truth(p)} when the raw forecast says {@code p}. */
    private static List<Calibration.Sample> runs(int n, DoubleUnaryOperator truth, long seed) {
        Random random = new Random(seed);
        List<Calibration.Sample> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double p = 0.05 + 0.9 * random.nextDouble();
            out.add(new Calibration.Sample(List.of(p, p), random.nextDouble() < truth.applyAsDouble(p)));
        }
        return out;
    }

    private static double brier(Calibration c, List<Calibration.Sample> runs) {
        double sum = 0;
        for (Calibration.Sample s : runs) {
            double q = c.apply(s.probabilities().get(0));
            double y = s.violated() ? 1 : 0;
            sum += (q - y) * (q - y);
        }
        return sum / runs.size();
    }

    @Test
    void anOverconfidentForecastIsPulledTowardsTheMiddle() {
        // the raw forecast says 0.9 where a quarter violate, 0.1 where a fifth do
        Calibration c = Calibration.fit(runs(400, p -> 0.2 + 0.1 * p, 1));
        assertTrue(c.slope() < 0.6, "slope " + c.slope());
        assertTrue(c.apply(0.9) < 0.45, "0.9 becomes " + c.apply(0.9));
        List<Calibration.Sample> unseen = runs(2000, p -> 0.2 + 0.1 * p, 2);
        assertTrue(brier(c, unseen) < brier(Calibration.IDENTITY, unseen),
                "calibrated " + brier(c, unseen) + " vs raw " + brier(Calibration.IDENTITY, unseen));
    }

    @Test
    void aCalibratedForecastIsLeftAboutAsItIs() {
        Calibration c = Calibration.fit(runs(2000, p -> p, 3));
        assertEquals(1.0, c.slope(), 0.15);
        assertEquals(0.0, c.intercept(), 0.15);
        assertEquals(0.7, c.apply(0.7), 0.03);
    }

    @Test
    void theMapKeepsTheOrderSoTheSameRunsReachTheThreshold() {
        // a forecast that carries no information at all: the slope stays at its floor, still increasing
        Calibration c = Calibration.fit(runs(400, p -> 0.3, 4));
        assertTrue(c.slope() >= Calibration.MIN_SLOPE, "slope " + c.slope());
        for (double p = 0.01; p < 0.99; p += 0.01) {
            assertTrue(c.apply(p + 0.01) > c.apply(p), "increasing at " + p);
        }
    }

    @Test
    void twoRunsMoveItHalfWayAsThePriorOfTwoRunsSays() {
        List<Calibration.Sample> two = new ArrayList<>();
        List<Calibration.Sample> twenty = new ArrayList<>();
        for (int i = 0; i < 20; i++) {
            Calibration.Sample held = new Calibration.Sample(List.of(0.9), false);
            twenty.add(held);
            if (i < 2) {
                two.add(held);
            }
        }
        double fromTwo = Calibration.fit(two).apply(0.9);
        double fromTwenty = Calibration.fit(twenty).apply(0.9);
        assertEquals(0.45, fromTwo, 0.05, "two runs that held at 0.9 against a prior of two runs saying 0.9");
        assertTrue(fromTwenty < 0.15, "twenty runs say more: " + fromTwenty);
    }

    @Test
    void noForecastNoCalibration() {
        assertSame(Calibration.IDENTITY, Calibration.fit(List.of(new Calibration.Sample(List.of(), true))));
        assertEquals(0.42, Calibration.IDENTITY.apply(0.42));
    }
}
