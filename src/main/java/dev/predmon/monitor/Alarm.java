package dev.predmon.monitor;

import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Bound;
import dev.predmon.property.UnderWay;

import java.util.List;
import java.util.function.Consumer;

/**
 * The alarm of the run being watched: current or gone. A warning lasts while its cause does; it ends
 * ({@link MonitorEvent.Recovered}) when the forecast no longer warns and the property's value rose above where it
 * warned (by {@value #RISE} of its distance to the bound, so that a noisy reading does not end it) and above the
 * lowest value of every training run that held, and a warning of
 * the thesis's matching, whose verdict never changes, only when the recommended action was under way too (the action
 * recovered the run). A violation ends when the property holds again. Either way the forecast starts over, and a later
 * warning or violation of the run is raised again. Also follows whether the action is under way
 * ({@link ActionProgress}, {@link MonitorEvent.UnderWay}).
 */
final class Alarm {

    /** How far above its value at the warning the property must rise, as a share of its distance to the bound. */
    static final double RISE = 0.05;

    private final Bound safety;
    private final ForecastTracker forecast;
    private final Consumer<MonitorEvent> events;
    private final ActionProgress action;
    private MonitorEvent.Warning active;
    private boolean violated;
    private boolean matchingSpent;

    /**
     * @param safety   the property, or null
     * @param forecast the run's forecast, or null
     */
    Alarm(Bound safety, ForecastTracker forecast, Consumer<MonitorEvent> events) {
        this.safety = safety;
        this.forecast = forecast;
        this.events = events;
        this.action = new ActionProgress(safety == null ? List.of() : safety.underWay());
    }

    /** A new run: no alarm, nothing under way. */
    void reset() {
        active = null;
        violated = false;
        matchingSpent = false;
        action.reset();
    }

    /** Whether a warning by {@code clause} may be raised now: no alarm is up, and the matching warns once a run. */
    boolean mayWarn(MonitorEvent.Clause clause) {
        return active == null && (clause != MonitorEvent.Clause.MATCHING || !matchingSpent);
    }

    /** Whether no warning is up. */
    boolean quiet() {
        return active == null;
    }

    /** Whether the property is violated now (since its violation, until it holds again). */
    boolean violated() {
        return violated;
    }

    void warned(MonitorEvent.Warning w) {
        active = w;
        matchingSpent |= w.clause() == MonitorEvent.Clause.MATCHING;
    }

    /**
     * The matching warned of another property than this alarm's (a faulty scenario that violates that one): it
     * warns once a run, and this alarm stays as it was.
     */
    void matchingSpent() {
        matchingSpent = true;
    }

    /** The property is violated from this reading on. */
    void violatedNow() {
        violated = true;
    }

    /** A record of the run: tells whether the action became under way or stopped being so. */
    void record(LogRecord r, int run) {
        UnderWay changed = action.record(r);
        if (changed != null) {
            events.accept(new MonitorEvent.UnderWay(r.time(), r.line(), changed.describe(), action.underWay(),
                    r.clock(), run));
        }
    }

    /**
     * A reading of the property, before the forecast takes it: after a violation, whether it holds again (the alarm
     * is then gone and the forecast starts over).
     */
    void holdsAgain(LogRecord r, double value, int run) {
        if (!violated || safety.violatedBy(value)) {
            return;
        }
        violated = false;
        active = null;
        if (forecast != null) {
            forecast.startOver();
        }
        events.accept(new MonitorEvent.Recovered(r.time(), r.line(), "property", value, "the property holds again ("
                + ForecastWords.fixed(value, 2) + ", at least " + ForecastWords.fixed(safety.floor(), 2) + ")",
                r.clock(), run, safety.id()));
    }

    /**
     * A reading of the property after the forecast took it: whether the warning's cause ended.
     *
     * @param f        the latest forecast, or null without one
     * @param warnsNow whether the forecast rule would warn on it now
     */
    void reading(LogRecord r, double value, Forecast f, boolean warnsNow, int run) {
        if (active == null || violated || warnsNow || active.value() == null) {
            return;
        }
        double at = active.value();
        double gap = Math.max(0, at - safety.floor());
        double floor = forecast == null ? Double.NaN : forecast.safeFloor();
        if (!(value > at && value - safety.floor() >= gap * (1 + RISE)) || value < floor) {
            return; // not risen enough, or still below every safe training run's lowest
        }
        boolean byAction = action.underWay() || action.since() >= active.time();
        if (active.clause() == MonitorEvent.Clause.MATCHING && !byAction) {
            return; // the matching's verdict stands: only the action recovers such a run
        }
        String rose = "the value rose from " + ForecastWords.fixed(at, 2) + " to " + ForecastWords.fixed(value, 2);
        String quiet = f == null ? "" : "; the forecast no longer warns (" + ForecastWords.probability(f)
                + ", warning at " + ForecastWords.fixed(forecast.threshold(), 2) + ")";
        String reason = byAction ? "recovered by the action, under way since line " + action.sinceLine() + ": " + rose
                + quiet : rose + quiet;
        active = null;
        if (forecast != null) {
            forecast.startOver();
        }
        events.accept(new MonitorEvent.Recovered(r.time(), r.line(), byAction ? "action" : "forecast", value, reason,
                r.clock(), run, safety.id()));
    }
}
