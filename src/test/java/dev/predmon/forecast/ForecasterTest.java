package dev.predmon.forecast;

import dev.predmon.pipeline.LogTrace;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static dev.predmon.forecast.ForecastTestRuns.run;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ForecasterTest {

    private static ForecastModel model(int safe, int violating) {
        List<LogTrace.Run> runs = new ArrayList<>();
        for (int i = 0; i < safe; i++) {
            runs.add(run(List.of("a/x", "b/y", "c/z"), new double[] {90, 80, 70}, Double.NaN));
        }
        for (int i = 0; i < violating; i++) {
            runs.add(run(List.of("a/x", "b/y", "c/z", "c/z"), new double[] {90, 50, 30, 10}, 3.0));
        }
        return StatsLearner.learn(ForecastTestRuns.machines(), runs, "s", 20.0).named("battery", List.of("battery"));
    }

    private static double afterB(ForecastModel m) {
        Forecaster f = new Forecaster(m, ForecastTestRuns.machines());
        f.pair("a", "x", 0, 90, 1);
        return f.pair("b", "y", 1, 50, 2).probability();
    }

    @Test
    void twoRunsCannotClaimCertainty() {
        double two = afterB(model(1, 2));
        double many = afterB(model(10, 20));
        assertTrue(two < 0.95, "2 violating runs give no certainty: " + two);
        assertTrue(many > two, "20 runs say more than 2: " + many + " vs " + two);
    }

    @Test
    void theValueSeparatesWhatTheStateDoesNot() {
        Forecaster f = new Forecaster(model(10, 10), ForecastTestRuns.machines());
        f.pair("a", "x", 0, 90, 1);
        double high = f.pair("b", "y", 1, 75, 2).probability();
        double low = f.reading(1.5, 35).probability();
        assertTrue(low > 0.8, "at 35 only violating runs were there: " + low);
        assertTrue(high < 0.6, "at 75 both kinds were: " + high);
        assertEquals(Forecast.Basis.MATCHED, f.reading(1.6, 34).basis());
    }

    @Test
    void anUnseenStepIsNovelThenMatchingResumesOnTheLatestPairs() {
        Forecaster f = new Forecaster(model(5, 5), ForecastTestRuns.machines());
        f.pair("a", "x", 0, 90, 10);
        Forecast novel = f.pair("c", "q", 1, 80, 11);
        assertEquals(Long.valueOf(11), novel.novelSince());
        assertEquals(Forecast.Basis.VALUE_ONLY, novel.basis(), "no state answers c/q");
        Forecast back = f.pair("c", "z", 2, 70, 12);
        assertEquals(Forecast.Basis.RESYNCHRONISED, back.basis(), "c/z is taken from state 4 on");
        assertEquals(Long.valueOf(11), back.novelSince(), "the novelty stays reported");
        assertTrue(back.runs() > 0);
    }

    @Test
    void aMessageTheModelsCannotReadMakesTheRunNovelAndCutsItsPast() {
        Forecaster f = new Forecaster(model(5, 5), ForecastTestRuns.machines());
        f.pair("a", "x", 0, 90, 10);
        f.unseen(11);
        Forecast gap = f.reading(1, 85);
        assertEquals(Long.valueOf(11), gap.novelSince());
        assertEquals(Forecast.Basis.VALUE_ONLY, gap.basis(), "the trace misses a step: no state is known");
        Forecast back = f.pair("b", "y", 2, 80, 12);
        assertEquals(Forecast.Basis.RESYNCHRONISED, back.basis(), "b/y alone, not a/x then b/y: " + back);
        f.unseen(13);
        assertEquals(Long.valueOf(11), f.reading(3, 75).novelSince(), "novel since the first such message");
        f.reset();
        assertNull(f.pair("a", "x", 0, 90, 20).novelSince(), "a new run starts known");
    }

    @Test
    void theTimeToViolationFollowsTheDrift() {
        Forecaster f = new Forecaster(model(3, 3), ForecastTestRuns.machines());
        f.pair("a", "x", 0, 90, 1);
        f.reading(1, 80);
        f.reading(2, 70);
        Forecast x = f.reading(3, 60);
        assertNotNull(x.timeToViolation());
        assertEquals(4.0, x.timeToViolation(), 1e-9, "60 falling 10 per second reaches 20 in 4 s");
        assertEquals(-10.0, x.drift(), 1e-9);
    }

    @Test
    void aRisingValueHasNoViolationInSightFromItsDrift() {
        Forecaster f = new Forecaster(model(3, 0), ForecastTestRuns.machines());
        f.pair("a", "x", 0, 50, 1);
        f.reading(1, 60);
        f.reading(2, 70);
        Forecast x = f.reading(3, 80);
        assertNull(x.timeToViolation(), x.toString());
    }

    @Test
    void aViolatedPropertyIsCertain() {
        Forecaster f = new Forecaster(model(3, 3), ForecastTestRuns.machines());
        f.pair("a", "x", 0, 50, 1);
        Forecast x = f.reading(1, 15);
        assertEquals(1.0, x.probability());
        assertEquals(Forecast.Basis.VIOLATED, x.basis());
    }

    @Test
    void theFileReadsBackWhatWasWritten() {
        ForecastModel m = model(4, 2).withThreshold(0.7, "chosen", true);
        assertEquals(m, ForecastFile.read(ForecastFile.write(m)));
        assertEquals(ForecastFile.write(m), ForecastFile.write(ForecastFile.read(ForecastFile.write(m))),
                "the same model gives the same bytes");
    }

    @Test
    void theCalibrationReadsBackAndAFileWithoutOneIsTheIdentity() {
        ForecastModel plain = model(4, 2).withThreshold(0.7, "chosen", true);
        ForecastModel m = plain.withCalibration(new Calibration(0.6, -0.4, 12));
        String text = ForecastFile.write(m);
        assertTrue(text.contains("\"calibration\""), text);
        assertEquals(m, ForecastFile.read(text));
        assertEquals(Calibration.IDENTITY, ForecastFile.read(ForecastFile.write(plain)).calibration());
        assertTrue(!ForecastFile.write(plain).contains("calibration"), "an identity map is not written");
    }

    @Test
    void theReportedProbabilityIsTheCalibratedOne() {
        ForecastModel m = model(4, 2);
        Calibration c = new Calibration(0.5, -0.3, 10);
        double raw = afterB(m);
        double calibrated = afterB(m.withCalibration(c));
        assertEquals(c.apply(raw), calibrated, 1e-12);
        assertTrue(Math.abs(calibrated - raw) > 0.01, raw + " vs " + calibrated);
    }
}
