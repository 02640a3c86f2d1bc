package dev.predmon.monitor;

import dev.predmon.compact.IoPair;
import dev.predmon.forecast.Forecast;
import dev.predmon.matching.Matching;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;

/**
 * A property followed with a forecast over the learned machines ({@link ForecastTracker}), written once for every
 * kind that has one (a bound's value forecast, {@link BoundFollow}; an absence's or a precedence's event forecast,
 * {@link EventFollow}): the forecast moved by each pair with the property's value as the kind reads it
 * ({@link #tracked}), told when it is news while the scope is open, started over when the scope opens or an alarm
 * ends, reset per run, unseen at a gap, and the status with the latest forecast as the kind shows it
 * ({@link #shown}). A kind adds its forecast at a record ({@link #follow}) and its warning ({@link #decide}).
 * Without a learned forecast ({@code tracker} null) the property is only checked.
 */
abstract class TrackedFollow extends FollowBase {

    /** The property's forecast over the machines, or null without one. */
    final ForecastTracker tracker;
    /** Whether the scope opened since the kind last judged its forecast. */
    boolean opened;

    TrackedFollow(int index, Property property, ForecastTracker tracker, FollowContext c) {
        super(index, property, c);
        this.tracker = tracker;
    }

    /** The property's value on the forecast's scale now, as the pairs move the forecast with it. */
    abstract double tracked();

    /** {@code f}, a forecast on the forecast's scale, as the property reads it (told, shown and warned). */
    abstract Forecast shown(Forecast f);

    @Override
    public void pair(IoPair pair, Matching.Step step, LogRecord trigger) {
        if (tracker == null) {
            return;
        }
        Forecast news = tracker.pair(pair.input(), pair.output(), trigger.time(), tracked(), trigger.line());
        if (open) {
            told(news, trigger);
        }
    }

    @Override
    public void gap(long line) {
        if (tracker != null) {
            tracker.unseen(line);
        }
    }

    @Override
    void opened(LogRecord r) {
        startOver();
        opened = true;
    }

    @Override
    void startOver() {
        if (tracker != null) {
            tracker.startOver();
        }
    }

    @Override
    public void reset() {
        super.reset();
        opened = false;
        if (tracker != null) {
            tracker.reset();
        }
    }

    @Override
    public void countTicksAs(TickSeconds t) {
        if (tracker != null) {
            tracker.countTicksAs(t);
        }
    }

    @Override
    public PropertyStatus status(PropertyChecker checker) {
        if (tracker == null) {
            return untracked(checker);
        }
        return new PropertyStatus(property, checker.verdict(index), PropertyStatus.Model.FORECAST, warned(), null,
                null, open ? last() : null);
    }

    /** The status of the property without a learned forecast. */
    PropertyStatus untracked(PropertyChecker checker) {
        return super.status(checker);
    }

    /** The latest forecast of the run as the property reads it, or null before one (or without a forecast). */
    final Forecast last() {
        return tracker == null || tracker.last() == null ? null : shown(tracker.last());
    }

    /**
     * Tells the replay's stream the latest forecast, and everyone {@code news} if it is news; returns the latest
     * forecast (on the forecast's scale).
     */
    final Forecast told(Forecast news, LogRecord r) {
        c.bounds.forecast(property.id(), shown(tracker.last()), c.now.run);
        if (news != null) {
            c.events.accept(new MonitorEvent.ForecastChanged(r.time(), r.line(), shown(news), r.clock(),
                    c.now.run, property.id()));
        }
        return tracker.last();
    }
}
