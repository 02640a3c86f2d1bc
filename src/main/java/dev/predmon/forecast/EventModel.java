package dev.predmon.forecast;

import dev.predmon.pipeline.LogTrace;
import dev.predmon.property.Absence;
import dev.predmon.property.Precedence;
import dev.predmon.property.Property;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.List;
import java.util.Map;

/**
 * The forecast of an absence ("a navigation never aborts") or a precedence ("no grasp before the arm is ready"): the
 * probability that the forbidden event (or the out-of-order one) comes in the rest of the run, from the states of the
 * learned machines the run is in. It is learned as a bound's is, from the training runs labelled by the property's own
 * violation ({@link EventRuns}): Prevent's per-state table of how many runs passed through each state and how many of
 * them went on to violate, with a Beta prior worth two runs whose mean is the base rate, calibrated, thresholded and
 * scored by the same cross-validation. Where nothing learned fits the run, it is the base rate.
 *
 * <p>Where the training runs cannot teach it (no run violated the property, every one did, or too few gave evidence
 * for it), the property has no forecast and says why ({@link #why}): a number there would be the prior speaking.
 *
 * @param runs      training runs with evidence for the property
 * @param violating how many of them violated it
 * @param model     its forecast, on the indicator's scale ({@link EventRuns}); null when it has none
 */
public record EventModel(int runs, int violating, ForecastModel model) {

    /** The property's indicator while it holds: the floor its forecast predicts the crossing of. */
    public static final double HOLDS = 1.0;
    /** The indicator once the property is violated. */
    public static final double BROKEN = 0.0;
    /** The fewest training runs with evidence for the property that a forecast is learned from. */
    public static final int MIN_RUNS = 5;

    public EventModel {
        if (runs < 0 || violating < 0 || violating > runs) {
            throw new IllegalArgumentException("counts out of range: " + violating + " of " + runs);
        }
        if (model != null && !forecastable(runs, violating)) {
            throw new IllegalArgumentException("a forecast from " + violating + " violating of " + runs + " runs: "
                    + why(runs, violating));
        }
    }

    /** Whether {@code violating} of {@code runs} training runs can teach a forecast. */
    public static boolean forecastable(int runs, int violating) {
        return runs >= MIN_RUNS && violating > 0 && violating < runs;
    }

    /**
     * The forecast of {@code p} over {@code machines} (by id), from the training runs {@code runs} ({@code unit}
     * their times'), or the counts alone when they cannot teach one.
     */
    public static EventModel learn(Map<String, CompactMealy<String, String>> machines, Property p,
                                   List<LogTrace.Run> runs, String unit) {
        List<LogTrace.Run> view = EventRuns.view(p, runs);
        int violating = (int) view.stream().filter(LogTrace.Run::violated).count();
        if (!forecastable(view.size(), violating)) {
            return new EventModel(view.size(), violating, null);
        }
        return new EventModel(view.size(), violating, StatsLearner.learn(machines, view, unit, HOLDS));
    }

    /** Whether the property has a forecast. */
    public boolean forecasts() {
        return model != null;
    }

    /** Why the property has no forecast, in words ({@code never violated in 43 training runs}); null with one. */
    public String why() {
        return model == null ? why(runs, violating) : null;
    }

    private static String why(int runs, int violating) {
        if (runs == 0) {
            return "no training run gave evidence of it";
        }
        if (violating == 0) {
            return "never violated in " + runs + " training run" + (runs == 1 ? "" : "s");
        }
        if (runs < MIN_RUNS) {
            return "only " + runs + " training run" + (runs == 1 ? "" : "s") + " gave evidence of it (a forecast is "
                    + "learned from " + MIN_RUNS + " or more)";
        }
        if (violating == runs) {
            return "violated in every one of the " + runs + " training runs: nothing tells a run that keeps it from "
                    + "one that does not";
        }
        return null;
    }

    /** Its scorecards (none without a forecast). */
    public List<Scorecard> scorecards() {
        return model == null ? List.of() : model.scorecards();
    }

    /** This model with {@code m} as its forecast (a forecastable one's, chosen by the cross-validation). */
    public EventModel with(ForecastModel m) {
        return new EventModel(runs, violating, m);
    }

    /**
     * Whether the property's rule warns on {@code f}: its probability reaches the threshold; or, where the
     * cross-validation chose the baseline, the base rate is at even odds or more (always saying the base rate warns
     * every run or none).
     */
    public boolean warns(Forecast f) {
        if (model == null || f.basis() == Forecast.Basis.VIOLATED) {
            return false;
        }
        return model.clauses().baseline() ? model.baseRate() >= ThresholdChoice.DEFAULT
                : f.probability() >= model.threshold();
    }

    /**
     * {@code f} as the property reads: no value and no drift (the indicator is no reading of the robot's), and a
     * forecast that no learned state fits rests on the base rate, not on a value.
     */
    public static Forecast shown(Forecast f) {
        if (f == null) {
            return null;
        }
        Forecast.Basis basis = f.basis() == Forecast.Basis.VALUE_ONLY ? Forecast.Basis.BASE_RATE : f.basis();
        return new Forecast(f.probability(), f.timeToViolation(), f.low(), f.high(), basis, f.novelSince(), f.runs(),
                f.violated(), null, null, f.unit());
    }

    /**
     * What violates {@code p}, in words: {@code GoTo/getStatus reply 3 comes} for an absence, {@code ArmService/grasp
     * command comes before any ArmService/ready reply} for a precedence.
     */
    public static String event(Property p) {
        if (p instanceof Absence a) {
            return a.event().describe() + " comes";
        }
        if (p instanceof Precedence q) {
            return q.then().describe() + " comes before any " + q.first().describe();
        }
        throw new IllegalArgumentException(p.kind() + " '" + p.id() + "' has no event forecast");
    }
}
