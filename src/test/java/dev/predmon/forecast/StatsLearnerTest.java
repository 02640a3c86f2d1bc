package dev.predmon.forecast;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static dev.predmon.forecast.ForecastTestRuns.run;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

class StatsLearnerTest {

    /** Two runs through the chain: a safe one that stays at 80..60, a violating one that falls to 30 and then below 20. */
    private static ForecastModel twoRuns() {
        return StatsLearner.learn(ForecastTestRuns.machines(), List.of(
                run(List.of("a/x", "b/y", "c/z"), new double[] {80, 70, 60}, Double.NaN),
                run(List.of("a/x", "b/y", "c/z", "c/z"), new double[] {60, 40, 30, 10}, 3.0)), "s", 20.0);
    }

    @Test
    void eachStateCountsTheRunsThroughItAndHowManyViolated() {
        ForecastModel m = twoRuns();
        Map<Integer, StateStats> states = m.states().get("chain");
        assertEquals(2, states.get(2).runs(), "both runs passed state 2 (after a/x)");
        assertEquals(1, states.get(2).violated());
        assertEquals(2, states.get(4).runs());
        assertNull(states.get(0), "the initial state is before any pair: no forecast is made there");
        assertEquals(2, m.runs());
        assertEquals(1, m.violating());
    }

    @Test
    void theTimeToTheViolationIsFromTheFirstVisitAndStopsAtTheViolation() {
        StateStats after = twoRuns().states().get("chain").get(4);
        // the violating run reached state 4 at t=1 and violated at t=3; its pair at t=3 is not counted
        assertEquals(2.0, after.toViolationMedian(), 1e-9);
        assertEquals(2.0, after.toEnd(), 1e-9, "the safe run reached it at t=1 and ended at t=3: censored at 2 s");
    }

    @Test
    void lowsByOutcomeAreCountedFromTheVisitOn() {
        Lows lows = twoRuns().states().get("chain").get(4).lows();
        assertEquals(1, lows.violating(35.0), "the violating run went as low as 30 before its violation");
        assertEquals(0, lows.runs(25.0), "no run went as low as 25 while safe");
        assertEquals(1, lows.runs(30.0), "only the violating run was at 30");
        assertEquals(2, lows.runs(60.0));
    }

    @Test
    void theDriftIsTheRateOfChangeWhileInTheState() {
        StateStats s = twoRuns().states().get("chain").get(2);
        // in state 2 (between a/x and b/y): the safe run fell 10 in 1 s, the violating one 20 in 1 s
        assertEquals(-15.0, s.drift(), 1e-9);
        assertEquals(5.0, s.driftSpread(), 1e-9);
        assertEquals(2, s.driftRuns());
    }
}
