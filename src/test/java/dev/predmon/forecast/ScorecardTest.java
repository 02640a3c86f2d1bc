package dev.predmon.forecast;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The scorecard's words and its place in {@code forecast.json}: stored, read back, optional, checked. */
class ScorecardTest {

    /** Like the scorecard of the 43 real recordings: 2 of 11 violations warned, a Brier score above the base rate's. */
    private static final Scorecard NO_SKILL = new Scorecard("battery level >= 20%", 5, 43, 11, 2, 1, 61, "ticks",
            0.2004, 0.1961);
    private static final Scorecard SKILL = new Scorecard("battery level >= 20%", 5, 30, 10, 10, 1, 8.5, "s", 0.188,
            0.222);

    private static ForecastModel model(List<Scorecard> cards) {
        Lows lows = new Lows(new double[] {30, 31}, new double[] {21});
        return new ForecastModel(ForecastModel.FORMAT, "ticks", 20, 43, 11, lows, 0.86, "chosen", true, Map.of(),
                List.of("a"), Calibration.IDENTITY, cards).named("battery", List.of("battery"));
    }

    @Test
    void aForecastNoBetterThanTheBaseRateHasNoSkillAndSaysSo() {
        assertFalse(NO_SKILL.skill());
        assertEquals(List.of("scorecard of 'battery level >= 20%' (5-fold cross-validation on 43 runs): warned 2 of "
                        + "11 violations, 1 false alarm(s) in 32 safe runs, median lead 61 ticks",
                "  Brier score 0.200 vs 0.196 for the base rate: the forecast has no skill on these models (it does "
                        + "no better than the base rate)"), NO_SKILL.lines());
        assertEquals("these models warned 2 of 11 violations in cross-validation, 1 false alarm(s) in 32 safe runs; "
                + "Brier 0.200 vs base rate 0.196", NO_SKILL.summary());
        assertTrue(SKILL.skill());
        assertTrue(SKILL.lines().get(0).endsWith("median lead 8.5 s"), SKILL.lines().get(0));
        Scorecard none = new Scorecard("p", 5, 10, 2, 0, 0, Double.NaN, "s", 0.2, 0.2);
        assertTrue(none.lines().get(0).endsWith("warned 0 of 2 violations, 0 false alarm(s) in 8 safe runs, no lead"));
        assertFalse(none.skill(), "equal to the base rate is no skill");
    }

    @Test
    void theMedianLead() {
        assertEquals(3, Scorecard.median(List.of(5.0, 1.0, 3.0)));
        assertEquals(2.5, Scorecard.median(List.of(4.0, 1.0)));
        assertTrue(Double.isNaN(Scorecard.median(List.of())));
    }

    @Test
    void forecastJsonKeepsTheScorecardsAndModelsWithoutOneStillRead() {
        ForecastModel m = model(List.of(NO_SKILL));
        String text = ForecastFile.write(m);
        assertTrue(text.contains("\"scorecards\""), text);
        assertEquals(m, ForecastFile.read(text));
        assertEquals(List.of(NO_SKILL), ForecastFile.read(text).scorecards());

        String without = ForecastFile.write(model(List.of()));
        assertFalse(without.contains("scorecards"), "written only when there is one");
        assertEquals(List.of(), ForecastFile.read(without).scorecards());
        Scorecard noLead = new Scorecard("p", 2, 4, 1, 0, 0, Double.NaN, "s", 0.25, 0.25);
        assertEquals(List.of(noLead), ForecastFile.read(ForecastFile.write(model(List.of(noLead)))).scorecards());
    }

    @Test
    void aScorecardThatCannotBeIsRefusedWithWhatIsWrong() {
        String text = ForecastFile.write(model(List.of(NO_SKILL)));
        IllegalArgumentException more = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(text.replace("\"warned\" : 2", "\"warned\" : 12")));
        assertTrue(more.getMessage().startsWith("'properties.battery.scorecards.0': the scorecard of 'battery level >= "
                + "20%"), more.getMessage());
        IllegalArgumentException brier = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(text.replace("\"brier\" : 0.2004", "\"brier\" : 7")));
        assertTrue(brier.getMessage().contains("Brier"), brier.getMessage());
        IllegalArgumentException missing = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(text.replace("\"folds\" : 5,", "")));
        assertEquals("'properties.battery.scorecards.0.folds' is missing", missing.getMessage());
        IllegalArgumentException notList = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(text.replaceFirst("\"scorecards\" : \\[", "\"scorecards\" : 3, \"x\" : [")));
        assertEquals("'properties.battery.scorecards': expected an array", notList.getMessage());
    }
}
