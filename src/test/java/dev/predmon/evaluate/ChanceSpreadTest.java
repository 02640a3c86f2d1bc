package dev.predmon.evaluate;

import org.junit.jupiter.api.Test;

import java.util.Collections;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ChanceSpreadTest {

    private static List<List<Double>> runs(int n, double p) {
        return Collections.nCopies(n, List.of(p));
    }

    @Test
    void oneRunAtEvenOddsIsAlwaysHalfWrong() {
        ChanceSpread s = ChanceSpread.of(runs(1, 0.5), 10);
        // the one run either violates (observed 1) or holds (observed 0): the error is 0.5 whichever happens
        assertEquals(0.5, s.eceBound(), 1e-12);
        assertEquals(0.0, s.observedLow().get(5), 1e-12);
        assertEquals(1.0, s.observedHigh().get(5), 1e-12);
        assertTrue(Double.isNaN(s.observedLow().get(4)), "a bin without forecasts has no range");
    }

    @Test
    void certainForecastsLeaveNoRoomForChance() {
        ChanceSpread s = ChanceSpread.of(runs(50, 0.0), 10);
        assertEquals(0.0, s.eceBound(), 1e-12);
        assertTrue(s.withinChance(0, 0.0));
        assertFalse(s.withinChance(0, 0.1), "a violation where a calibrated 0 says none is more than chance");
    }

    @Test
    void theBoundShrinksAsTheSquareRootOfTheRuns() {
        // 90th percentile of |mean of n Bernoulli(0.25) - 0.25|: about 1.645 * sqrt(0.1875 / n)
        double forty = ChanceSpread.of(runs(40, 0.25), 10).eceBound();
        double fourHundred = ChanceSpread.of(runs(400, 0.25), 10).eceBound();
        assertEquals(1.645 * Math.sqrt(0.1875 / 40), forty, 0.03);
        assertEquals(1.645 * Math.sqrt(0.1875 / 400), fourHundred, 0.01);
        assertTrue(fourHundred < forty / 2.5);
    }

    @Test
    void eachBinIsJudgedByWhatTheRunSaidThere() {
        // a run that said 0 early and 1 late: a calibrated forecast's low bin never comes true, its high bin always
        ChanceSpread s = ChanceSpread.of(List.of(List.of(0.0, 1.0), List.of(0.0)), 10);
        assertEquals(0.0, s.observedHigh().get(0), 1e-12);
        assertEquals(1.0, s.observedLow().get(9), 1e-12);
        assertEquals(0.0, s.eceBound(), 1e-12);
        assertFalse(s.withinChance(0, 1 / 3.0), "the run violating while its early forecast said 0 is more than chance");
    }

    @Test
    void theSameRunsGiveTheSameSpread() {
        List<List<Double>> r = List.of(List.of(0.2, 0.3), List.of(0.7), List.of(0.4, 0.45, 0.9));
        assertEquals(ChanceSpread.of(r, 10), ChanceSpread.of(r, 10));
    }
}
