package dev.predmon.forecast;

import dev.predmon.compact.IoPair;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import dev.predmon.property.Bound;
import dev.predmon.property.Scope;
import dev.predmon.property.ValueReader;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A bound property other than the safety property is forecast from the runs as it sees them ({@link BoundRuns}):
 * labelled by its own violation, its own values; a ceiling mirrored so that one forecaster serves it.
 */
class BoundForecastTest {

    private static final ValueReader TEMP = new ValueReader("Thermo", "read", "/thermo", "/client");
    /** A ceiling: the temperature at most 70. */
    private static final Bound HOT = new Bound("hot", "temperature <= 70", "cool down", Scope.GLOBAL, TEMP,
            Double.NEGATIVE_INFINITY, 70);

    /**
     * A run of {@code pairs}, one a second from t=0, the safety property never read, {@code hot} reading
     * {@code temps[i]} at pair i and violated at {@code violation} (NaN: held).
     */
    private static LogTrace.Run run(List<String> pairs, double[] temps, double violation) {
        return run("hot", pairs, temps, violation);
    }

    /** As above, for the property {@code id}. */
    private static LogTrace.Run run(String id, List<String> pairs, double[] temps, double violation) {
        List<IoPair> io = new ArrayList<>();
        double[] times = new double[pairs.size()];
        double[] none = new double[pairs.size()];
        List<RunTiming.Reading> readings = new ArrayList<>();
        for (int i = 0; i < pairs.size(); i++) {
            String[] p = pairs.get(i).split("/", -1);
            io.add(new IoPair(p[0], p[1], null, null));
            times[i] = i;
            none[i] = Double.NaN;
            readings.add(new RunTiming.Reading(i, temps[i], i));
        }
        RunTiming t = new RunTiming(times, none, Double.NaN, pairs.size(), Double.NaN, "s", List.of(), List.of(),
                List.of(), Double.isNaN(violation) ? Map.of() : Map.of(id, violation), Map.of(id, readings));
        return new LogTrace.Run(0, 1, io, false, Map.of(), t);
    }

    private static final LogTrace.Run HEATS = run(List.of("a/x", "b/y", "c/z", "c/z"), new double[] {60, 64, 68, 72},
            3);
    private static final LogTrace.Run STAYS = run(List.of("a/x", "b/y", "c/z"), new double[] {50, 52, 51}, Double.NaN);

    @Test
    void aCeilingIsAFloorOfTheMirroredValueLabelledByItsOwnViolation() {
        List<LogTrace.Run> runs = List.of(HEATS, STAYS);
        assertEquals(BoundModel.CEILING, BoundRuns.side(HOT, runs));
        List<LogTrace.Run> view = BoundRuns.view(HOT, BoundModel.CEILING, runs);
        assertTrue(view.get(0).violated(), "the run is labelled by the ceiling's violation, not the safety property's");
        assertFalse(view.get(1).violated());
        assertArrayEquals(new double[] {-60, -64, -68, -72}, view.get(0).timing().values());
        assertEquals(3, view.get(0).timing().violationTime());
        assertEquals(-68, view.get(0).timing().lowestSafeValue(), "the highest temperature before the violation");
        assertEquals(-52, view.get(1).timing().lowestSafeValue(), "the highest temperature of the run that held");

        ForecastModel m = StatsLearner.learn(ForecastTestRuns.machines(), view, "s",
                BoundModel.limit(HOT, BoundModel.CEILING));
        assertEquals(-70, m.limit());
        assertEquals(2, m.runs());
        assertEquals(1, m.violating());
        assertArrayEquals(new double[] {-68}, m.lows().violating());
        assertArrayEquals(new double[] {-52}, m.lows().safe());
    }

    @Test
    void theTimeToACeilingIsItsDistanceOverTheRise() {
        List<LogTrace.Run> view = BoundRuns.view(HOT, BoundModel.CEILING, List.of(HEATS, STAYS));
        BoundModel hot = new BoundModel(BoundModel.CEILING, StatsLearner.learn(ForecastTestRuns.machines(), view, "s",
                -70));
        Forecaster f = new Forecaster(hot.model(), ForecastTestRuns.machines());
        f.pair("a", "x", 0, hot.value(60), 1);
        f.pair("b", "y", 1, hot.value(63), 2);
        Forecast at66 = hot.shown(f.pair("c", "z", 2, hot.value(66), 3));
        // rising 3 a second, 4 below the ceiling: 4/3 s to the violation
        assertEquals(4.0 / 3, at66.timeToViolation(), 1e-9);
        assertEquals(66, at66.value());
        assertEquals(3, at66.drift(), 1e-9);
        assertEquals(Forecast.Basis.MATCHED, at66.basis());
        Forecast past = hot.shown(f.reading(3, hot.value(71)));
        assertEquals(Forecast.Basis.VIOLATED, past.basis(), "71 is above the ceiling 70");
        assertEquals(1.0, past.probability());
    }

    @Test
    void aBoundWithBothSidesIsForecastOnTheSideItsRunsCrossed() {
        Bound band = new Bound("band", "10 <= temperature <= 70", null, Scope.GLOBAL, TEMP, 10, 70);
        LogTrace.Run hot = run("band", List.of("a/x", "b/y"), new double[] {60, 75}, 1);
        LogTrace.Run cold = run("band", List.of("a/x", "b/y"), new double[] {20, 5}, 1);
        assertEquals(BoundModel.CEILING, BoundRuns.side(band, List.of(hot, hot, cold)));
        assertEquals(BoundModel.FLOOR, BoundRuns.side(band, List.of(hot, cold)), "a tie: the floor");
        assertEquals(BoundModel.FLOOR, BoundRuns.side(band, List.of(STAYS)), "no violation: the floor");
        Bound floor = new Bound("reserve", "reserve", null, TEMP, 30);
        assertEquals(BoundModel.FLOOR, BoundRuns.side(floor, List.of(HEATS)));
        assertNull(BoundRuns.side(new Bound("none", "none", null, Scope.GLOBAL, TEMP, Double.NEGATIVE_INFINITY,
                Double.POSITIVE_INFINITY), List.of(HEATS)));
    }

    @Test
    void forecastJsonKeepsEachBoundsForecastByItsId() {
        ForecastModel safety = StatsLearner.learn(ForecastTestRuns.machines(), List.of(STAYS), "s", 20)
                .withThreshold(0.7, "0.70 chosen", true).named("safe", List.of("safe"));
        ForecastModel own = StatsLearner.learn(ForecastTestRuns.machines(),
                BoundRuns.view(HOT, BoundModel.CEILING, List.of(HEATS, STAYS)), "s", -70)
                .withCalibration(new Calibration(1.5, -0.25, 12)).withThreshold(0.4, "0.40 by hand", true);
        ForecastModel both = safety.withBounds(Map.of("hot", new BoundModel(BoundModel.CEILING, own)))
                .named("safe", List.of("safe", "hot"));
        String text = ForecastFile.write(both);
        assertTrue(text.contains("\"safe\" : {\n      \"kind\" : \"bound\",\n      \"side\" : \"floor\",\n      "
                + "\"limit\" : 20.0"), "the first floor as any other bound: " + text);
        assertTrue(text.contains("\"hot\" : {\n      \"kind\" : \"bound\",\n      \"side\" : \"ceiling\",\n      "
                + "\"limit\" : -70.0"), text);
        ForecastModel read = ForecastFile.read(text);
        assertEquals(both, read);
        assertEquals(0.4, read.bounds().get("hot").model().threshold());
        assertEquals(safety, ForecastFile.read(ForecastFile.write(safety)), "a model of one property");
        assertFalse(ForecastFile.write(safety).contains("\"hot\""), "one entry, the first floor's");

        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(text.replace("\"side\" : \"ceiling\"", "\"side\" : \"up\"")));
        assertEquals("'properties.hot.side': side 'up': expected floor or ceiling", bad.getMessage());
        IllegalArgumentException missing = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(text.replace("\"side\" : \"ceiling\",", "")));
        assertEquals("'properties.hot.side' is missing", missing.getMessage());
    }
}
