package dev.predmon.forecast;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What the cross-validation chose goes into {@code forecast.json} and back (the curves by where an obligation began,
 * the novelty margin, the baseline in force, the scorecard beside its baseline's), and a file written before any of it
 * reads as every clause of the forecast's rule with the half margin and the pooled curve.
 */
class ForecastChoiceFileTest {

    private static double[] durations(int n, double from) {
        double[] d = new double[n];
        for (int i = 0; i < n; i++) {
            d[i] = from + i;
        }
        return d;
    }

    @Test
    void everyChoiceReadsBackAsWritten() {
        Survival legs = new Survival(durations(10, 5), durations(0, 0));
        Survival pooled = new Survival(durations(30, 5), new double[] {3}).withContexts(Map.of(
                "goTo_ch_i>goTo_ki_i", legs, "goTo_ki_i", new Survival(durations(20, 5), new double[0]),
                "goTo_ch_i", new Survival(new double[] {1, 2}, new double[] {2, 2, 2, 2, 2, 2, 2, 2, 2, 2}),
                "halt_ch_i", new Survival(new double[] {1}, new double[] {2, 2})));
        // a curve needs ten discharged obligations: goTo_ch_i's ten censored ones do not make one, its two discharged
        // ones make only a late bound (its estimates are the pooled curve's); one discharged obligation makes nothing
        assertEquals(List.of("goTo_ch_i", "goTo_ch_i>goTo_ki_i", "goTo_ki_i"),
                List.copyOf(pooled.contexts().keySet()));
        assertEquals(legs, pooled.at("goTo_ch_i>goTo_ki_i"));
        assertEquals(20, pooled.at("start>goTo_ki_i").size(), "unknown condition: its trigger's input");
        Survival station = pooled.at("goTo_ch_i");
        assertEquals(pooled.size(), station.size());
        assertEquals(pooled.estimate(4, 10), station.estimate(4, 10));
        assertEquals(34.0, station.lateAfter(0.99), 1e-9, "two legs bound little: capped at the property's longest");
        assertSame(pooled, pooled.at("halt_ch_i"));
        assertSame(pooled, pooled.at(null));

        Scorecard base = new Scorecard("nav", 5, 40, 2, 2, 0, 100, "ticks", 0.1, 0.1, Scorecard.OBLIGATIONS,
                Scorecard.ELAPSED, null, false);
        Scorecard card = new Scorecard("nav", 5, 40, 2, 1, 1, 50, "ticks", 0.05, 0.1, Scorecard.OBLIGATIONS,
                Scorecard.FORECAST, base, true);
        ForecastModel m = new ForecastModel(ForecastModel.FORMAT, "s", 20, 10, 2, new Lows(new double[] {30},
                new double[] {25}), 0.6, "chosen", true, Map.of(), List.of("a"), Calibration.IDENTITY, List.of(),
                Map.of("nav", pooled), Map.of("nav", new DeadlineRule(0.7, "n", true, Calibration.IDENTITY, 0, true)))
                .withClauses(Clauses.NO_MATCHING).withDeadlineScorecards(Map.of("nav", List.of(card)))
                .named("battery", List.of("battery", "nav"));
        ForecastModel back = ForecastFile.read(ForecastFile.write(m));
        assertEquals(m, back);
        assertEquals(0.0, back.deadlineRule("nav").margin());
        assertTrue(back.deadlineRule("nav").baseline());
        assertEquals(base, back.property("nav").orElseThrow().scorecards().get(0).inForce());
        assertEquals(Clauses.NO_MATCHING, back.clauses());
        assertEquals(Clauses.BASELINE, ForecastFile.read(ForecastFile.write(m.withClauses(Clauses.BASELINE)))
                .clauses());
    }

    /**
     * {@code learn} gives the forecast an (empty) entry for every bounded response after the cross-validation chose
     * its clauses: whatever was chosen (the baseline alone, the rule without the matching, every clause) is what the
     * model written to {@code forecast.json} warns by.
     */
    @Test
    void theChosenClausesSurviveTheEntriesForEveryDeadline() {
        Abstraction thesis = AbstractionFiles.builtin("thesis").orElseThrow();
        ForecastModel m = new ForecastModel(ForecastModel.FORMAT, "s", 20, 10, 2, new Lows(new double[] {30},
                new double[] {25}), 0.6, "chosen", true, Map.of(), List.of("a"));
        for (Clauses c : List.of(Clauses.BASELINE, Clauses.NO_MATCHING, Clauses.ALL)) {
            ForecastModel covered = PropertyParts.covering(m.withClauses(c), thesis);
            assertTrue(covered.obligations().containsKey("navigation-in-time"), covered.obligations().toString());
            assertEquals(c, covered.clauses());
            assertEquals(c, ForecastFile.read(ForecastFile.write(covered)).clauses());
        }
        assertFalse(PropertyParts.covering(m.withClauses(Clauses.BASELINE), thesis).matchingWarns());
        ForecastModel chosen = m.withClauses(Clauses.NO_MATCHING);
        for (ForecastModel changed : List.of(chosen.withObligations(Map.of()), chosen.withDeadlines(Map.of()),
                chosen.withBounds(Map.of()), chosen.withEvents(Map.of()), chosen.withThreshold(0.7, "n", true),
                chosen.withCalibration(Calibration.IDENTITY), chosen.withScorecards(List.of()))) {
            assertEquals(Clauses.NO_MATCHING, changed.clauses(), "no other part of the model resets the choice");
        }
    }

    /**
     * Models learned before the choice (a copy of the shipped forecast of format 1): every clause, the half margin, no
     * curve by condition.
     */
    @Test
    void aForecastLearnedBeforeTheChoiceStillReadsAsBefore() throws Exception {
        ForecastModel shipped = ForecastFile.read(Files.readString(Path.of("src/test/resources/forecast/format-1",
                ForecastFile.NAME)));
        assertEquals(Clauses.ALL, shipped.clauses());
        shipped.deadlines().values().forEach(r -> assertEquals(DeadlineRule.HALF, r.margin()));
        shipped.obligations().values().forEach(s -> assertTrue(s.contexts().isEmpty()));
        shipped.scorecards().forEach(c -> assertEquals(null, c.baseline()));
    }
}
