package dev.predmon.monitor;

import dev.predmon.compact.IoPair;
import dev.predmon.forecast.EventModel;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.matching.Matching;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.Map;

/**
 * An absence or a precedence followed through a run with its event forecast ({@link EventModel}): after each pair,
 * the probability that the forbidden event (or the out-of-order one) comes in the rest of the run, from the states of
 * the learned machines the run is in, told when it changes ({@link MonitorEvent.ForecastChanged}) while its scope is
 * open, and its warning when that probability reaches the threshold the cross-validation chose. The warning ends
 * ({@link MonitorEvent.Recovered}, cause {@code forecast}) when the run moved on to states where the probability fell
 * {@value ForecastTracker#STEP} below the threshold, so that a forecast hovering at it does not flap. Its violation,
 * "holds again" and the end of its alarms are the checker's ({@link FollowBase}). A property whose training runs could
 * not teach a forecast says why in its status ({@link EventModel#why}), and is only checked.
 */
final class EventFollow extends TrackedFollow {

    private final EventModel model;
    /** Whether the forecast knows of the violation (its indicator fell to {@link EventModel#BROKEN}). */
    private boolean broken;

    EventFollow(int index, Property property, EventModel model, Map<String, CompactMealy<String, String>> machines,
                FollowContext c) {
        super(index, property, model.forecasts() ? ForecastTracker.of(model.model(), machines) : null, c);
        this.model = model;
    }

    @Override
    void follow(PropertyChecker checker, LogRecord r, boolean in) {
        if (tracker == null) {
            return;
        }
        if (violated && !broken) {
            broken = true;
            Forecast f = tracker.reading(r.time(), EventModel.BROKEN); // the forecast learns of the violation
            if (in) {
                told(f, r);
            }
        } else if (opened && in) {
            opened = false;
            told(tracker.reading(r.time(), indicator()), r);
        }
    }

    @Override
    public void pair(IoPair pair, Matching.Step step, LogRecord trigger) {
        super.pair(pair, step, trigger);
        if (open) {
            opened = false; // the forecast in the states the run is in was told
        }
    }

    @Override
    public void decide(IoPair pair, Matching.Step step, LogRecord trigger) {
        if (tracker == null || !open || tracker.last() == null) {
            return;
        }
        Forecast f = EventModel.shown(tracker.last());
        if (active != null && !violated && active.clause() == MonitorEvent.Clause.FORECAST
                && !model.model().clauses().baseline() && f.probability() < tracker.threshold() - ForecastTracker.STEP) {
            ended(trigger, "forecast", Double.NaN, label() + ": the forecast no longer warns (" + ForecastWords
                    .probability(f) + ", warning at " + ForecastWords.fixed(tracker.threshold(), 2) + ") "
                    + where(pair));
            return;
        }
        if (!c.forecastRule() || active != null || violated || !model.warns(f)) {
            return;
        }
        var faulty = c.faultyAlive();
        warn(new MonitorEvent.Warning(trigger.time(), trigger.line(), faulty, null, c.now.pairs, trigger.clock(),
                c.now.run, c.rule, f, reason(f, where(pair)), MonitorEvent.Clause.FORECAST, c.likeliestFaulty(faulty),
                property.id()));
    }

    @Override
    void startOver() {
        super.startOver();
        broken = false;
    }

    @Override
    public void reset() {
        super.reset();
        broken = false;
    }

    @Override
    PropertyStatus untracked(PropertyChecker checker) {
        return new PropertyStatus(property, checker.verdict(index), PropertyStatus.Model.NONE, warned(), null,
                null, null, model.why());
    }

    @Override
    double tracked() {
        return indicator();
    }

    @Override
    Forecast shown(Forecast f) {
        return EventModel.shown(f);
    }

    /** The pair a recovery or a warning was made after, in words (built only for one: a decision runs every pair). */
    private static String where(IoPair pair) {
        return "after " + pair.input() + " -> " + pair.output();
    }

    /** The property's indicator now: {@link EventModel#BROKEN} once violated, else {@link EventModel#HOLDS}. */
    private double indicator() {
        return violated ? EventModel.BROKEN : EventModel.HOLDS;
    }

    /**
     * In an operator's words: "'no navigation aborts' (no-abort): P(violation) 0.62 that a GoTo/getStatus reply 3
     * comes in the rest of the run, reaching the warning threshold 0.55; about 40 s to the violation; 5 of 8
     * training runs that were in this state violated; after goTo_ki_i -> goTo_ki_o".
     */
    private String reason(Forecast f, String where) {
        String why = model.model().clauses().baseline()
                ? "the training runs violated it at even odds or more (the base rate, which did better than the "
                + "forecast on the held-out folds)"
                : "reaching the warning threshold " + ForecastWords.fixed(tracker.threshold(), 2);
        return label() + ": " + ForecastWords.probability(f) + " that " + EventModel.event(property)
                + " in the rest of the run, " + why + "; " + ForecastWords.time(f) + "; " + ForecastWords.evidence(f)
                + "; " + where + (property.action() == null ? "" : "; do now: " + property.action());
    }
}
