package dev.predmon.learn;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.Clauses;
import dev.predmon.forecast.CrossValidation;
import dev.predmon.forecast.EventModel;
import dev.predmon.forecast.EventRuns;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.Scorecard;
import dev.predmon.forecast.ThresholdChoice;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.property.Absence;
import dev.predmon.property.Precedence;
import dev.predmon.property.Property;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Learns the event forecast of every absence and precedence ({@link EventModel}) and chooses its rule by the one
 * cross-validation that chooses every property's ({@link CrossValidation}), on the replays the bounds are chosen on
 * ({@link HeldOutFolds}): each fold's models carry the event forecasts learned without its logs, and each held-out run
 * is forecast as {@code watch}'s own monitor forecast it. The cross-validation fits the calibration and the threshold,
 * and scores the rule beside the property's baseline on the same runs: always saying the base rate (the share of the
 * fold's training runs that violated it), which warns every run where that share is at even odds or more and none
 * where it is not. A baseline that says the same of every run is compared by wrong calls (misses and false alarms
 * alike), not recall first ({@link CrossValidation.Space#constantBaseline}). Where the rule did worse, the baseline
 * warns.
 */
public final class EventTraining {

    /** The baseline's words in a scorecard. */
    static final String BASE_RATE = "base rate: warn every run if the training runs violated it at even odds or more,"
            + " else none";
    /** Why a model warns by the base rate, after its threshold's note. */
    static final String BASELINE_NOTE = "the base rate warns: the forecast's rule did worse on the same folds";

    private EventTraining() {
    }

    /** The absences and precedences of {@code abstraction}, in its order: each gets an event forecast. */
    public static List<Property> properties(Abstraction abstraction) {
        return abstraction.properties().stream().filter(p -> p instanceof Absence || p instanceof Precedence)
                .toList();
    }

    /**
     * By id, the event forecast of every absence and precedence of {@code abstraction} that {@code runs} can teach,
     * over {@code machines}, warning never (the held-out replays' models: what is chosen after needs their forecasts
     * only).
     */
    static Map<String, EventModel> heldOut(Map<String, CompactMealy<String, String>> machines, Abstraction abstraction,
                                           List<LogTrace.Run> runs, String unit) {
        Map<String, EventModel> out = new TreeMap<>();
        for (Property p : properties(abstraction)) {
            EventModel e = EventModel.learn(machines, p, runs, unit);
            if (e.forecasts()) {
                out.put(p.id(), e.with(e.model().withThreshold(HeldOutRun.NEVER, "held out", true)));
            }
        }
        return out;
    }

    /** Whether {@code runs} can teach any absence's or precedence's forecast. */
    static boolean teaches(Abstraction abstraction, List<LogTrace.Run> runs) {
        for (Property p : properties(abstraction)) {
            List<LogTrace.Run> view = EventRuns.view(p, runs);
            if (EventModel.forecastable(view.size(), (int) view.stream().filter(LogTrace.Run::violated).count())) {
                return true;
            }
        }
        return false;
    }

    /**
     * By id, the event forecast of every absence and precedence of {@code abstraction} learned from {@code runs} over
     * {@code machines}, each with its rule chosen on {@code heldOut} and its scorecard; or, where the runs cannot
     * teach one, why.
     */
    public static Map<String, EventModel> train(Map<String, CompactMealy<String, String>> machines,
                                                Abstraction abstraction, List<LogTrace.Run> runs, String unit,
                                                HeldOutFolds heldOut) {
        Map<String, EventModel> out = new TreeMap<>();
        for (Property p : properties(abstraction)) {
            EventModel e = EventModel.learn(machines, p, runs, unit);
            if (!e.forecasts()) {
                out.put(p.id(), e);
                continue;
            }
            List<CrossValidation.Case> cases = new ArrayList<>();
            for (HeldOutFolds.Fold fold : heldOut.judged()) {
                HeldOutFolds.BoundFold f = fold.events().get(p.id());
                if (f != null) {
                    f.runs().forEach(r -> cases.add(HeldOutCases.event(fold.index(), r, f.baseRate())));
                }
            }
            if (heldOut.folds() == 0 || cases.isEmpty()) {
                String note = "default " + ThresholdChoice.DEFAULT + ": " + (heldOut.folds() == 0
                        ? "too few logs to cross-validate" : "no fold's training runs could teach a forecast");
                out.put(p.id(), e.with(e.model().withThreshold(ThresholdChoice.DEFAULT, note, false)));
                continue;
            }
            out.put(p.id(), e.with(chosen(e.model(), p.name(), heldOut.folds(), unit, cases)));
        }
        return out;
    }

    /** {@code m} with the rule the cross-validation chose on {@code cases}, and its scorecard beside the baseline's. */
    private static ForecastModel chosen(ForecastModel m, String property, int folds, String unit,
                                        List<CrossValidation.Case> cases) {
        CrossValidation.Choice c = CrossValidation.choose(cases, folds, new CrossValidation.Space(0, 0,
                Scorecard.RUNS, true), new Scorecard.Names(property, unit, Scorecard.RUNS, Scorecard.FORECAST, BASE_RATE));
        CrossValidation.Rule r = c.rule();
        String note = c.baseline() ? r.note() + "; " + BASELINE_NOTE : r.note();
        ForecastModel chosen = m.withThreshold(r.threshold(), note, r.validated())
                .withScorecards(c.scorecard() == null ? List.of() : List.of(c.scorecard()))
                .withClauses(c.baseline() ? Clauses.BASELINE : Clauses.NO_MATCHING);
        return r.validated() ? chosen.withCalibration(r.calibration()) : chosen;
    }
}
