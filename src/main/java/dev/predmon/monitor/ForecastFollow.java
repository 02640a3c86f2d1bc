package dev.predmon.monitor;

import dev.predmon.compact.IoPair;
import dev.predmon.forecast.Forecast;
import dev.predmon.matching.Matching;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.ObjIntConsumer;

/**
 * The forecast's property followed through the runs of a log, for the {@link PredictiveMonitor}: each new value (its
 * violation, the recovery the {@link Alarm} sees), the forecast after each value and each pair, and the warnings the
 * {@link WarningPolicy} decides on them. It keeps the log's first warning and first violation of the property.
 */
final class ForecastFollow {

    private final Bound bound;
    private final ForecastTracker forecast;
    private final Alarm alarm;
    private final WarningPolicy policy;
    private final Matching matching;
    private final RunState now;
    private final WarningRule rule;
    private final String property;
    private final Consumer<MonitorEvent> events;
    /** By faulty scenario, the property its runs violate when its {@code scenario.json} names one. */
    private final Map<String, Property> violates;
    private ObjIntConsumer<Forecast> everyForecast = (f, r) -> { };
    private MonitorEvent.Warning firstWarning;
    private MonitorEvent.Violation firstViolation;
    /** The other bound properties' value forecasts, or null. */
    private BoundWatch bounds;

    /**
     * @param bound    the forecast's property, null without one
     * @param forecast the forecast, null for models without one
     * @param property the property's id, null without one
     * @param violates by faulty scenario, the property its runs violate when its {@code scenario.json} names one
     *                 ({@code violates}); a scenario not in it violates {@code property}
     */
    ForecastFollow(Bound bound, ForecastTracker forecast, Alarm alarm, WarningPolicy policy, Matching matching,
                   RunState now, WarningRule rule, String property, Map<String, Property> violates,
                   Consumer<MonitorEvent> events) {
        this.violates = Map.copyOf(violates);
        this.bound = bound;
        this.forecast = forecast;
        this.alarm = alarm;
        this.policy = policy;
        this.matching = matching;
        this.now = now;
        this.rule = rule;
        this.property = property;
        this.events = events;
    }

    /** The property's value {@code v}, read from {@code record}: its violation, recovery, forecast and warning. */
    void reading(LogRecord record, double v) {
        int run = now.run;
        Double before = now.value;
        now.value = v;
        if (!alarm.violated() && bound.violatedBy(v)) {
            MonitorEvent.Violation violation = new MonitorEvent.Violation(record.time(), record.line(), bound.id(),
                    bound.name(), v, before, bound.violation(v), record.clock(), run, true);
            now.violation = now.violation == null ? violation : now.violation;
            firstViolation = firstViolation == null ? violation : firstViolation;
            alarm.violatedNow();
            events.accept(violation);
        }
        alarm.holdsAgain(record, v, run);
        if (forecast != null && (before == null || before != v)) {
            Forecast f = told(forecast.reading(record.time(), v), record);
            alarm.reading(record, v, f, policy.forecastWarns(f, !matching.nominalAlive()), run);
            WarningPolicy.Decision d = policy.atReading(f, v, !matching.nominalAlive());
            if (d != null) {
                warn(record, matching.faultyAlive(), d.reason(), f, d.clause());
            }
        } else if (forecast == null) {
            alarm.reading(record, v, null, false, run); // models without a forecast: recovered by the action alone
        }
    }

    /** A compacted pair, {@code step} its matching: the forecast after it, and a warning if the policy decides one. */
    void pair(IoPair pair, Matching.Step step, LogRecord trigger) {
        Forecast f = forecast == null ? null : told(forecast.pair(pair.input(), pair.output(), trigger.time(),
                now.value == null ? Double.NaN : now.value, trigger.line()), trigger);
        WarningPolicy.Decision d = policy.atPair(pair, step, f);
        if (d != null) {
            warn(trigger, step.faultyAlive(), d.reason(), f, d.clause());
        }
        if (bounds != null) {
            bounds.pair(pair, step, trigger);
        }
    }

    /** A gap in the trace at {@code line}: the forecasts' runs are novel from there. */
    void unseen(long line) {
        if (forecast != null) {
            forecast.unseen(line);
        }
        if (bounds != null) {
            bounds.unseen(line);
        }
    }

    /** Also forecasts the other bound properties after each pair ({@link BoundWatch#pair}). */
    void forecastBounds(BoundWatch bounds) {
        this.bounds = bounds;
    }

    /** Also tells {@code each} every forecast with its run ({@link PredictiveMonitor#onEveryForecast}). */
    void onEveryForecast(ObjIntConsumer<Forecast> each) {
        this.everyForecast = each;
    }

    /** The log's first warning of the property (of any run), or null. */
    MonitorEvent.Warning firstWarning() {
        return firstWarning;
    }

    /** The log's first violation of the property (of any run), or null. */
    MonitorEvent.Violation firstViolation() {
        return firstViolation;
    }

    /** Reports {@code news} if it is news, and returns the latest forecast. */
    private Forecast told(Forecast news, LogRecord trigger) {
        Forecast f = forecast.last();
        everyForecast.accept(f, now.run);
        if (news != null) {
            events.accept(new MonitorEvent.ForecastChanged(trigger.time(), trigger.line(), news, trigger.clock(),
                    now.run, property));
        }
        return f;
    }

    /**
     * Tells a warning. The matching's names the property the likeliest faulty scenario still matching violates (its
     * {@code violates}): a warning of another property than the forecast's counts as the run's warning of some
     * property, like a deadline's, and leaves the forecast's alarm as it was.
     */
    private void warn(LogRecord trigger, List<String> faultyAlive, String reason, Forecast f,
                      MonitorEvent.Clause clause) {
        String scenario = matching.likeliestFaulty(faultyAlive);
        Property other = clause == MonitorEvent.Clause.MATCHING && scenario != null ? violates.get(scenario) : null;
        String about = other == null ? property : other.id();
        String why = Objects.equals(about, property) ? reason : "'" + other.name() + "' (" + other.id()
                + "), which faulty scenario " + scenario + " violates: " + reason;
        MonitorEvent.Warning w = new MonitorEvent.Warning(trigger.time(), trigger.line(), faultyAlive, now.value,
                now.pairs, trigger.clock(), now.run, rule, f, why, clause, scenario, about);
        if (Objects.equals(about, property)) {
            now.warning = now.warning == null ? w : now.warning; // the run's outcome keeps its first warning
            firstWarning = firstWarning == null ? w : firstWarning;
            alarm.warned(w);
        } else {
            now.otherWarned(about);
            alarm.matchingSpent();
        }
        now.anyWarned(w);
        events.accept(w);
    }
}
