package dev.predmon.forecast;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The value tables' counts, and where the runs that held are likely to stop. */
class LowsTest {

    @Test
    void theSafeFloorIsTheLowestValueARunThatHeldWentTo() {
        Lows lows = new Lows(new double[] {38, 30, 31, 32, 33, 34, 35, 36, 37}, new double[] {21, 22});
        assertEquals(30.0, lows.safeFloor(), 1e-9);
        assertEquals(40.0, new Lows(new double[] {40}, new double[] {21}).safeFloor(), 1e-9);
        assertTrue(Double.isNaN(new Lows(new double[0], new double[] {21}).safeFloor()));
    }

    @Test
    void theNoveltyClauseWarnsBelowTheLowestSafeRunWithoutAMargin() {
        Lows lows = new Lows(new double[] {30, 31, 32, 33, 34, 35, 36, 37, 38}, new double[] {21, 22, 23});
        ForecastModel m = new ForecastModel(ForecastModel.FORMAT, "s", 20, 12, 3, lows, 0.9, "test", true,
                Map.of(), List.of());
        assertFalse(m.belowSafeFloor(30.0), "as low as a run that held went");
        assertTrue(m.belowSafeFloor(29.9), "a robot stuck below every safe run is warned at once");
        ForecastModel noSafe = new ForecastModel(ForecastModel.FORMAT, "s", 20, 3, 3,
                new Lows(new double[0], new double[] {21, 22, 23}), 0.9, "test", true, Map.of(), List.of());
        assertFalse(noSafe.belowSafeFloor(5), "no run held: no floor to be below");
    }

    @Test
    void belowEverySafeRunANewSafeRunStillCountsOnceInNPlusOne() {
        Lows lows = new Lows(new double[] {38, 40, 42}, new double[] {21, 22, 23});
        assertEquals(3 + 3 / 4.0, lows.weight(30), 1e-9, "below every safe run: the violating runs and 3/4 of a safe one");
        assertEquals(3 + 3 / 4.0, lows.weight(37.9), 1e-9, "just below the lowest of 3 safe runs: 3/4 of one");
        assertEquals(4.0, lows.weight(38), 1e-9, "as low as a safe run went: counted as it is");
        Lows smoothed = lows.smoothed(ForecastModel.PRIOR_RUNS, 0.5);
        assertEquals((3 + 2 * 0.5) / (3.75 + 2), smoothed.monotoneRate(37.9), 1e-9, "3 of 3 violating runs as low, and 3/4 of a safe one");
    }
}
