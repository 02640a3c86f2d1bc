package dev.predmon.monitor;

import dev.predmon.compact.IoPair;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.matching.Matching;

/**
 * The one home of the warning decision of the forecast's property: given what the monitor just saw (a new value of
 * the property with its forecast, or a pair with its matching step and forecast) and the {@link Alarm}'s state, whether
 * the rule in force warns, by which clause and why. {@link PredictiveMonitor} only feeds it and tells the warning;
 * {@code learn} scores the same decisions by replaying held-out logs through that monitor.
 *
 * <ul>
 *   <li>{@link WarningRule#MATCH}, the thesis's rule: every nominal model eliminated while a faulty one still matches
 *       ({@code confirm} pairs on, {@link Matching.Step#ruleWarns()}).</li>
 *   <li>{@link WarningRule#FORECAST}: the forecast's probability reaches the threshold, or the run is beyond the safe
 *       training runs with its value below theirs ({@link ForecastTracker#warns}); the thesis's verdict too, but only
 *       when every nominal model was contradicted while the run does what the models know
 *       ({@link ForecastTracker#takesMatching}).</li>
 * </ul>
 * A warning is raised only while no alarm is up, never while the property is violated (under the forecast rule), and
 * the matching's once a run ({@link Alarm#mayWarn}).
 */
final class WarningPolicy {

    /** A warning to raise: its clause and its reason in an operator's words. */
    record Decision(MonitorEvent.Clause clause, String reason) {
    }

    private final WarningRule rule;
    /** The forecast, or null for models without one (then the rule is the match rule). */
    private final ForecastTracker forecast;
    private final Alarm alarm;

    WarningPolicy(WarningRule rule, ForecastTracker forecast, Alarm alarm) {
        this.rule = rule;
        this.forecast = forecast;
        this.alarm = alarm;
    }

    /** Whether the forecast rule warns on {@code f}, {@code beyondNominal} when no nominal model matches any more. */
    boolean forecastWarns(Forecast f, boolean beyondNominal) {
        return rule == WarningRule.FORECAST && f != null && forecast.warns(f, beyondNominal);
    }

    /**
     * Of a bound property other than the forecast's ({@link BoundWatch}), forecast {@code f} on its forecast's scale
     * ({@code shown} as the property reads, {@code ceiling} when it is a ceiling's): the warning to raise, or null. Only the forecast rule warns of such a
     * property (the thesis's matching is about the forecast's property), by the same clauses, once while no alarm of
     * the property is up ({@code alarmUp}: a warning, or its violation).
     */
    static Decision ofBound(WarningRule rule, ForecastTracker tracker, Forecast f, Forecast shown, boolean ceiling,
                            boolean beyondNominal, boolean alarmUp, String where) {
        if (rule != WarningRule.FORECAST || f == null || alarmUp || !tracker.warns(f, beyondNominal)) {
            return null;
        }
        return new Decision(tracker.clause(f), tracker.reason(shown, where, ceiling));
    }

    /** At a new value {@code value} of the property, forecast {@code f}: the warning to raise, or null. */
    Decision atReading(Forecast f, double value, boolean beyondNominal) {
        if (!forecastWarns(f, beyondNominal) || alarm.violated() || !alarm.mayWarn(forecast.clause(f))) {
            return null;
        }
        return new Decision(forecast.clause(f), forecast.reason(f, "at the new reading "
                + ForecastWords.fixed(value, 2)));
    }

    /** After {@code pair}, matched as {@code step}, forecast {@code f} (null without a forecast): the warning, or null. */
    Decision atPair(IoPair pair, Matching.Step step, Forecast f) {
        if (!alarm.quiet() || (rule != WarningRule.MATCH && alarm.violated())) {
            return null;
        }
        MonitorEvent.Clause matching = MonitorEvent.Clause.MATCHING;
        if (step.ruleWarns() && (rule == WarningRule.MATCH || (ForecastTracker.takesMatching(f, step)
                && (forecast == null || forecast.matchingWarns()))) && alarm.mayWarn(matching)) {
            return new Decision(matching, MonitorEvent.Warning.onlyFaulty(step.faultyAlive())
                    + (f == null ? "" : "; " + ForecastWords.line(f)));
        }
        if (forecastWarns(f, !step.nominalAlive())) {
            return new Decision(forecast.clause(f), forecast.reason(f, "after " + pair.input() + " -> "
                    + pair.output()));
        }
        return null;
    }
}
