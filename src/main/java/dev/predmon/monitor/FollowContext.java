package dev.predmon.monitor;

import dev.predmon.forecast.Survival;
import dev.predmon.matching.Matching;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Response;

import java.util.List;
import java.util.function.Consumer;

/**
 * What every property's follower ({@link PropertyFollow}) shares in one log: the run being watched, the rule that
 * warns, where events go, the matching (which faulty scenarios still match), the id of the property the run's
 * outcome headlines (kept for the outcome's older fields and the wire's {@code battery} names, not a code path) and
 * who else hears every forecast (the replay's streams).
 */
final class FollowContext {

    final RunState now;
    final WarningRule rule;
    final Consumer<MonitorEvent> events;
    private final Matching matching;
    /** The headline property's id, or null without one. */
    final String headline;
    /** Told every value forecast of every bound, as the property reads. */
    BoundSteps bounds = (p, f, run) -> { };
    /** Told every deadline judgement and every forecast obligation's end. */
    DeadlineSteps deadlines = new DeadlineSteps() {
        @Override
        public void forecast(int run, Response property, LogRecord record, double elapsed, Survival.Estimate raw,
                             Survival curve) {
        }

        @Override
        public void ended(int run, Response property, LogRecord record, double duration, boolean discharged) {
        }
    };

    FollowContext(RunState now, WarningRule rule, Consumer<MonitorEvent> events, Matching matching, String headline) {
        this.now = now;
        this.rule = rule;
        this.events = events;
        this.matching = matching;
        this.headline = headline;
    }

    /** Whether the forecast rule is in force: only then do the forecasts' own clauses warn. */
    boolean forecastRule() {
        return rule == WarningRule.FORECAST;
    }

    /** Whether no nominal model matches the run any more (what the novelty clause asks). */
    boolean beyondNominal() {
        return matching != null && !matching.nominalAlive();
    }

    /** The faulty scenarios still matching the run. */
    List<String> faultyAlive() {
        return matching == null ? List.of() : matching.faultyAlive();
    }

    /** The likeliest of {@code faulty}, or null. */
    String likeliestFaulty(List<String> faulty) {
        return matching == null ? null : matching.likeliestFaulty(faulty);
    }
}
