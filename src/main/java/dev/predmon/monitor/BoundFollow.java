package dev.predmon.monitor;

import dev.predmon.compact.IoPair;
import dev.predmon.forecast.BoundModel;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.matching.Matching;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Bound;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.UnderWay;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.Map;

/**
 * A bound property followed through a run, floor or ceiling, whole run or scoped, every one the same way: the value
 * forecast the models learned for it ({@link BoundModel}; none without one), told when it changes
 * ({@link MonitorEvent.ForecastChanged}) at each new value and after each pair while its scope is open, and its
 * warning by the forecast rule's clauses. The warning ends ({@link MonitorEvent.Recovered}) when the forecast no
 * longer warns and the value moved back from the bound past where it warned (by {@value #RISE} of its distance, so
 * that a noisy reading does not end it) and past every safe training run's extreme; a warning of the thesis's
 * matching, whose verdict never changes, only when the property's action was under way too (the action recovered the
 * run; {@link ActionProgress}, {@link MonitorEvent.UnderWay}). Its violation and "holds again" are the checker's
 * ({@link FollowBase}), its forecast's pairs, resets and status those of every tracked kind ({@link TrackedFollow}).
 * Out of its scope the forecast follows the run untold; when the scope opens it starts over.
 */
final class BoundFollow extends TrackedFollow {

    /** How far back from the bound the value must move past where it warned, as a share of its distance to it. */
    static final double RISE = 0.05;

    private final Bound bound;
    /** The learned forecast and its side, or null without one. */
    private final BoundModel model;
    /** The bound the forecast predicts the crossing of, on the forecast's scale. */
    private final double limit;
    private final ActionProgress action;
    /** The last value on the forecast's scale, and as read; NaN before one. */
    private double value = Double.NaN;
    private double raw = Double.NaN;

    /** The bound {@code bound}, property {@code index}, forecast by {@code model} over {@code machines} if not null. */
    BoundFollow(int index, Bound bound, BoundModel model, Map<String, CompactMealy<String, String>> machines,
                FollowContext c) {
        super(index, bound, model == null ? null : ForecastTracker.of(model.model(), machines), c);
        this.bound = bound;
        this.model = model;
        this.limit = BoundModel.limit(bound, model == null ? BoundModel.FLOOR : model.side());
        this.action = new ActionProgress(bound.underWay());
    }

    @Override
    void follow(PropertyChecker checker, LogRecord r, boolean in) {
        UnderWay changed = action.record(r);
        if (changed != null) {
            c.events.accept(new MonitorEvent.UnderWay(r.time(), r.line(), changed.describe(), action.underWay(),
                    r.clock(), c.now.run));
        }
        double read = checker.value(index); // whatever the scope: the forecast follows the whole run
        if (Double.isNaN(read)) {
            return;
        }
        double v = scale(read);
        boolean news = v != value || opened;
        value = v;
        raw = read;
        opened = false;
        if (tracker == null) {
            if (in) {
                recover(r, null); // no forecast: recovered by the value and the action alone
            }
            return;
        }
        if (!news) {
            return;
        }
        if (!in) {
            tracker.reading(r.time(), v); // followed, not told: the property is not checked here
            return;
        }
        Forecast f = told(tracker.reading(r.time(), v), r);
        recover(r, f);
        decide(f, r, null, read);
    }

    @Override
    public void decide(IoPair pair, Matching.Step step, LogRecord trigger) {
        if (tracker != null && open) {
            decide(tracker.last(), trigger, pair, Double.NaN);
        }
    }

    @Override
    public Double value() {
        return Double.isNaN(raw) ? null : raw;
    }

    /** Whether the run read the property's value at all (without one, "held" would be a verdict on no evidence). */
    boolean observed() {
        return !Double.isNaN(raw);
    }

    @Override
    public void reset() {
        super.reset();
        value = Double.NaN;
        raw = Double.NaN;
        action.reset();
    }

    @Override
    double tracked() {
        return value;
    }

    @Override
    Forecast shown(Forecast f) {
        return model.shown(f);
    }

    /** {@code v} as read on the forecast's scale (mirrored for a ceiling's). */
    private double scale(double v) {
        return model == null ? v : model.value(v);
    }

    /** At a new value, {@code f} the forecast on it (null without one): whether the warning's cause ended. */
    private void recover(LogRecord r, Forecast f) {
        if (active == null || violated || active.value() == null) {
            return;
        }
        if (c.forecastRule() && f != null && tracker.warns(f, c.beyondNominal())) {
            return;
        }
        double at = scale(active.value());
        double gap = Math.max(0, at - limit);
        double safe = tracker == null ? Double.NaN : tracker.safeFloor();
        if (!(value > at && value - limit >= gap * (1 + RISE)) || value < safe) {
            return; // not moved back enough, or still past every safe training run's extreme
        }
        boolean byAction = action.underWay() || action.since() >= active.time();
        if (active.clause() == MonitorEvent.Clause.MATCHING && !byAction) {
            return; // the matching's verdict stands: only the action recovers such a run
        }
        String moved = "the value moved back from " + ForecastWords.fixed(active.value(), 2) + " to "
                + ForecastWords.fixed(raw, 2);
        String quiet = f == null ? "" : "; the forecast no longer warns (" + ForecastWords.probability(f)
                + ", warning at " + ForecastWords.fixed(tracker.threshold(), 2) + ")";
        String reason = label() + ": " + (byAction ? "recovered by the action, under way since line "
                + action.sinceLine() + ": " : "") + moved + quiet;
        startOver();
        ended(r, byAction ? "action" : "forecast", raw, reason);
    }

    /**
     * The forecast rule's warning on {@code f}, made at {@code r} after {@code pair}, or at the new reading
     * {@code read} when {@code pair} is null, if it warns. Where it was made is put in words only for a warning: a
     * reading is judged at every record that carries one.
     */
    private void decide(Forecast f, LogRecord r, IoPair pair, double read) {
        if (!c.forecastRule() || f == null || active != null || violated || !tracker.warns(f, c.beyondNominal())) {
            return;
        }
        String where = pair != null ? "after " + pair.input() + " -> " + pair.output()
                : "at the new reading " + ForecastWords.fixed(read, 2);
        Forecast shown = model.shown(f);
        String reason = label() + ": " + tracker.reason(shown, where, model.mirrored())
                + (bound.action() == null ? "" : "; do now: " + bound.action());
        var faulty = c.faultyAlive();
        warn(new MonitorEvent.Warning(r.time(), r.line(), faulty, value(), c.now.pairs, r.clock(), c.now.run, c.rule,
                shown, reason, tracker.clause(f), c.likeliestFaulty(faulty), property.id()));
    }
}
