package dev.predmon.monitor;

import dev.predmon.compact.IoPair;
import dev.predmon.forecast.BoundModel;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.matching.Matching;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;

import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;

/**
 * The value forecast of every bound property other than the forecast's own ({@link BoundModel}), for the
 * {@link SafetyMonitor}: each property follows the run's pairs with a {@link ForecastTracker} of its own, is forecast
 * at each new value of it and after each pair, and warns as the {@link WarningPolicy} decides for it, once while its
 * cause lasts. Its forecast is told ({@link MonitorEvent.ForecastChanged}) when it changes as the forecast's
 * property's is, its warning names the property and its action. The warning ends ({@link MonitorEvent.Recovered})
 * when the forecast no longer warns and the value moved back from the bound past where it warned (by
 * {@link Alarm#RISE} of its distance) and past every safe training run's extreme; the violation, when the property
 * holds again. Constant state per property.
 *
 * <p>A property with a scope is forecast and warned only while its scope is open, as the checker sees it ({@link
 * PropertyChecker#inScope}): outside it the property cannot be violated, so nothing is told of it (no forecast, no
 * warning) and its value outside counts for no violation. When the scope closes, a warning or a violation still up
 * ends ({@link #SCOPE}); when it opens, the forecast starts over, as the check does, from the states the run is in.
 */
public final class BoundWatch {

    /**
     * Told every forecast of each bound property with a value forecast of its own (not the forecast's), as the property
     * reads, one per pair and per new value of it: the stream of the held-out replays
     * ({@link PredictiveMonitor#onEveryBoundForecast}).
     */
    public interface Every {
        /** A forecast of {@code property} in run {@code run}. */
        void forecast(String property, Forecast f, int run);
    }

    /** The cause of a recovery that the property's scope closed. */
    static final String SCOPE = "scope";

    private Every every = (p, f, r) -> { };

    private final Bound[] bounds;
    private final BoundModel[] models;
    private final ForecastTracker[] trackers;
    private final WarningRule rule;
    private final RunState now;
    private final Consumer<MonitorEvent> events;
    /** Each property's last value on the forecast's scale (NaN before one). */
    private final double[] value;
    /** Each property's value (forecast's scale) at its warning while one is up, else NaN. */
    private final double[] warnedAt;
    private final boolean[] violated;
    /** Whether each property's scope is open (always, for the whole run). */
    private final boolean[] open;
    /** Whether each property's scope opened since its last value. */
    private final boolean[] opened;

    /** The forecasts {@code models} carry for the bound {@code properties}; none without a forecast. */
    BoundWatch(List<Property> properties, ModelSet models, WarningRule rule, RunState now,
               Consumer<MonitorEvent> events) {
        int n = properties.size();
        this.bounds = new Bound[n];
        this.models = new BoundModel[n];
        this.trackers = new ForecastTracker[n];
        this.rule = rule;
        this.now = now;
        this.events = events;
        this.value = new double[n];
        this.warnedAt = new double[n];
        this.violated = new boolean[n];
        this.open = new boolean[n];
        this.opened = new boolean[n];
        for (int i = 0; i < n; i++) {
            BoundModel m = models.forecast() == null ? null : models.forecast().bounds().get(properties.get(i).id());
            if (properties.get(i) instanceof Bound b && m != null) {
                bounds[i] = b;
                this.models[i] = m;
                trackers[i] = ForecastTracker.of(m.model(), models.machines());
            }
        }
        reset();
    }

    /** Whether property {@code index} has a value forecast here. */
    boolean forecasts(int index) {
        return bounds[index] != null;
    }

    /** Whether a warning of property {@code index} is up. */
    boolean warned(int index) {
        return !Double.isNaN(warnedAt[index]);
    }

    /** The latest forecast of property {@code index} as the property reads, or null before one or out of its scope. */
    Forecast current(int index) {
        return trackers[index] == null || !open[index] ? null : models[index].shown(trackers[index].last());
    }

    /** Reports every forecast's times in seconds, a tick lasting {@code t}. */
    void countTicksAs(TickSeconds t) {
        for (ForecastTracker f : trackers) {
            if (f != null) {
                f.countTicksAs(t);
            }
        }
    }

    /** A new run. */
    void reset() {
        Arrays.fill(value, Double.NaN);
        Arrays.fill(warnedAt, Double.NaN);
        Arrays.fill(violated, false);
        Arrays.fill(opened, false);
        for (int i = 0; i < bounds.length; i++) {
            open[i] = bounds[i] != null && bounds[i].scope().global();
        }
        for (ForecastTracker f : trackers) {
            if (f != null) {
                f.reset();
            }
        }
    }

    /** After {@code checker} took {@code r}: each property's new value, its forecast, warning and recovery. */
    void record(PropertyChecker checker, LogRecord r, boolean beyondNominal) {
        for (int i = 0; i < bounds.length; i++) {
            if (bounds[i] == null) {
                continue;
            }
            scope(i, checker.inScope(i), r);
            double raw = checker.value(i);
            if (Double.isNaN(raw)) {
                continue;
            }
            double v = models[i].value(raw);
            if (v == value[i] && !opened[i]) {
                continue;
            }
            value[i] = v;
            opened[i] = false; // the segment's first value is judged, even if it did not change
            if (!open[i]) {
                trackers[i].reading(r.time(), v); // followed, not told: the property is not checked here
                continue;
            }
            if (bounds[i].violatedBy(raw)) {
                violated[i] = true;
                warnedAt[i] = Double.NaN; // the violation overtakes the warning
            } else if (violated[i]) {
                violated[i] = false;
                trackers[i].startOver();
                events.accept(new MonitorEvent.Recovered(r.time(), r.line(), "property", raw, "'" + bounds[i].name()
                        + "' (" + bounds[i].id() + ") holds again (" + ForecastWords.fixed(raw, 2) + ")", r.clock(),
                        now.run, bounds[i].id()));
            }
            Forecast f = told(i, trackers[i].reading(r.time(), v), r);
            if (recovered(i, f, beyondNominal)) {
                trackers[i].startOver();
                events.accept(new MonitorEvent.Recovered(r.time(), r.line(), "forecast", raw, "'" + bounds[i].name()
                        + "' (" + bounds[i].id() + "): the value moved back to " + ForecastWords.fixed(raw, 2)
                        + "; the forecast no longer warns (" + ForecastWords.probability(f) + ")", r.clock(), now.run,
                        bounds[i].id()));
                warnedAt[i] = Double.NaN;
            }
            decide(i, f, beyondNominal, r, "at the new reading " + ForecastWords.fixed(raw, 2));
        }
    }

    /** A compacted pair, {@code step} its matching: every property's forecast after it, and its warning. */
    void pair(IoPair pair, Matching.Step step, LogRecord trigger) {
        for (int i = 0; i < bounds.length; i++) {
            if (bounds[i] == null) {
                continue;
            }
            Forecast news = trackers[i].pair(pair.input(), pair.output(), trigger.time(), value[i], trigger.line());
            if (!open[i]) {
                continue;
            }
            Forecast f = told(i, news, trigger);
            decide(i, f, !step.nominalAlive(), trigger, "after " + pair.input() + " -> " + pair.output());
        }
    }

    /** A gap in the trace at {@code line}: every property's run is novel from there. */
    void unseen(long line) {
        for (ForecastTracker f : trackers) {
            if (f != null) {
                f.unseen(line);
            }
        }
    }

    /** Also tells {@code each} every forecast. */
    void onEveryForecast(Every each) {
        this.every = each;
    }

    /**
     * Property {@code i}'s scope is {@code in} after record {@code r}: when it opens, the forecast starts over (and
     * tells its next forecast); when it closes, a warning or violation still up ends, for the property holds there.
     */
    private void scope(int i, boolean in, LogRecord r) {
        if (in == open[i]) {
            return;
        }
        open[i] = in;
        if (in) {
            trackers[i].startOver();
            opened[i] = true;
            return;
        }
        if (warned(i) || violated[i]) {
            double raw = Double.isNaN(value[i]) ? Double.NaN : models[i].value(value[i]);
            Bound b = bounds[i];
            events.accept(new MonitorEvent.Recovered(r.time(), r.line(), SCOPE, raw, "'" + b.name() + "' ("
                    + b.id() + "): out of its scope at " + b.scope().until().describe() + "; not checked until "
                    + b.scope().from().describe() + " again", r.clock(), now.run, b.id()));
        }
        warnedAt[i] = Double.NaN;
        violated[i] = false;
    }

    /** Reports {@code news} of property {@code i} if it is news; returns its latest forecast (forecast's scale). */
    private Forecast told(int i, Forecast news, LogRecord r) {
        every.forecast(bounds[i].id(), models[i].shown(trackers[i].last()), now.run);
        if (news != null) {
            events.accept(new MonitorEvent.ForecastChanged(r.time(), r.line(), models[i].shown(news), r.clock(),
                    now.run, bounds[i].id()));
        }
        return trackers[i].last();
    }

    private boolean recovered(int i, Forecast f, boolean beyondNominal) {
        if (!warned(i) || violated[i] || trackers[i].warns(f, beyondNominal)) {
            return false;
        }
        double limit = models[i].model().limit();
        double gap = Math.max(0, warnedAt[i] - limit);
        double floor = trackers[i].safeFloor();
        return value[i] > warnedAt[i] && value[i] - limit >= gap * (1 + Alarm.RISE) && !(value[i] < floor);
    }

    private void decide(int i, Forecast f, boolean beyondNominal, LogRecord r, String where) {
        Forecast shown = models[i].shown(f);
        WarningPolicy.Decision d = WarningPolicy.ofBound(rule, trackers[i], f, shown, models[i].mirrored(), beyondNominal,
                warned(i) || violated[i], where);
        if (d == null) {
            return;
        }
        warnedAt[i] = value[i];
        Bound b = bounds[i];
        String reason = "'" + b.name() + "' (" + b.id() + "): " + d.reason()
                + (b.action() == null ? "" : "; do now: " + b.action());
        MonitorEvent.Warning w = new MonitorEvent.Warning(r.time(), r.line(), List.of(),
                Double.isNaN(value[i]) ? null : models[i].value(value[i]), now.pairs, r.clock(), now.run, rule, shown,
                reason, d.clause(), null, b.id());
        now.anyWarned(w);
        events.accept(w);
    }
}
