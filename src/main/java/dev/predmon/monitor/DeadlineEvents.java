package dev.predmon.monitor;

import dev.predmon.forecast.Survival;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Response;

import java.util.List;
import java.util.function.Consumer;

/**
 * What the bounded responses' deadline forecasts ({@link DeadlineWatch}) say, as the monitor's events: a warning of
 * the property (which counts as the run's warning of some property), its recovery when the obligation is discharged,
 * and its forecast when it changes as shown; and, to whoever asks ({@link DeadlineSteps}), every judgement and every
 * obligation's end.
 */
final class DeadlineEvents implements DeadlineWatch.Listener {

    private final RunState now;
    private final WarningRule rule;
    private final Consumer<MonitorEvent> events;
    /** Also told every judgement and every obligation's end, or null. */
    private DeadlineSteps steps;

    DeadlineEvents(RunState now, WarningRule rule, Consumer<MonitorEvent> events) {
        this.now = now;
        this.rule = rule;
        this.events = events;
    }

    /** Also tells {@code each} every deadline forecast and every forecast obligation's end. */
    void steps(DeadlineSteps each) {
        this.steps = each;
    }

    @Override
    public void judged(LogRecord r, Response p, double elapsed, Survival.Estimate raw) {
        if (steps != null) {
            steps.forecast(now.run, p, r, elapsed, raw);
        }
    }

    @Override
    public void ended(LogRecord r, Response p, double duration, boolean discharged) {
        if (steps != null) {
            steps.ended(now.run, p, r, duration, discharged);
        }
    }

    @Override
    public void due(LogRecord r, DeadlineWatch.Due d) {
        // A bounded response has no value: the warning carries none, as its violation and its recovery do not.
        MonitorEvent.Warning w = new MonitorEvent.Warning(r.time(), r.line(), List.of(), null, now.pairs,
                r.clock(), now.run, rule, null, d.reason(), MonitorEvent.Clause.DEADLINE, null, d.property().id(),
                d.estimate());
        now.anyWarned(w);
        events.accept(w);
    }

    @Override
    public void recovered(LogRecord r, Response p, String reason) {
        events.accept(new MonitorEvent.Recovered(r.time(), r.line(), "discharged", Double.NaN, reason, r.clock(),
                now.run, p.id()));
    }

    @Override
    public void changed(LogRecord r, Response p, Survival.Estimate e) {
        events.accept(new MonitorEvent.ForecastChanged(r.time(), r.line(), null, r.clock(), now.run, p.id(), e,
                p.within().unit().key));
    }
}
