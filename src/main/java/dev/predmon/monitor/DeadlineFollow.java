package dev.predmon.monitor;

import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.forecast.Survival;
import dev.predmon.parse.LogRecord;
import dev.predmon.pipeline.TriggerInputs;
import dev.predmon.property.Deadline;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.Response;

import java.util.List;
import java.util.Locale;

/**
 * A bounded response whose training obligations the models measured, followed through a run: while an obligation
 * is pending, how likely it is to miss its deadline given how long it has been pending, against how long the training
 * runs' obligations took ({@link Survival}, Kaplan-Meier with the runs that stopped early censored).
 *
 * <p>Under the forecast rule it warns once per obligation, by the property's {@link DeadlineRule}: when the calibrated
 * P(miss) reaches the threshold learned by cross-validation (even odds when the training obligations could not choose
 * one), or by the rule's clause whatever the probability: the obligation is late for its leg (past the prediction
 * bound of the training obligations that began where it did, {@link Survival#lateAfter}), or, in rules without it,
 * it has been pending longer than every training obligation (no evidence either way) and the rule's margin of the
 * time from the longest of them to the deadline has passed too. A warned obligation discharged in time
 * ends its warning (cause {@code discharged}); one that misses its deadline is the property's violation, told by the
 * checker. While an obligation is pending its calibrated forecast is told when it changes as the page shows it: the
 * probability of a miss in whole percent, or that the obligation is past every training one. A property without a
 * training obligation gets no such follower: no verdict on no evidence.
 */
final class DeadlineFollow extends FollowBase {

    /** Codes of {@link #shownCode} besides a percent: nothing told yet, novel, under 1% and over 99%. */
    private static final int NONE = Integer.MIN_VALUE;
    private static final int NOVEL = Integer.MIN_VALUE + 1;
    private static final int BELOW_1 = Integer.MIN_VALUE + 2;
    private static final int ABOVE_99 = Integer.MIN_VALUE + 3;

    private final Response response;
    private final Survival survival;
    private final DeadlineRule rule;
    /** Where each obligation began, for the curve it is judged by ({@link Survival#at}). */
    private final TriggerInputs triggers;
    /** The curve the pending obligation is judged by: its trigger input's own, else the pooled one; null when none is. */
    private Survival pending;
    /**
     * The line of the trigger of the obligation judged ({@link PropertyChecker#pendingLine}), -1 when none is: of
     * several open at once, the one nearest its deadline.
     */
    private long line = -1;
    /** The forecast of the obligation pending now, or null. */
    private Survival.Estimate current;
    /** The pending obligation's forecast as last told ({@link #shownCode} of {@link #shown}), {@link #NONE} before. */
    private int told = NONE;
    /** Whether an obligation ended at the last record, whether discharged, and after how long. */
    private boolean ended;
    private boolean discharged;
    private double duration;
    /** The pending obligation's elapsed time when it was last judged, NaN before. */
    private double judgedAt = Double.NaN;

    DeadlineFollow(int index, Response response, Survival survival, DeadlineRule rule, TriggerInputs triggers,
                   FollowContext c) {
        super(index, response, c);
        this.triggers = triggers;
        this.response = response;
        this.survival = survival;
        this.rule = rule;
    }

    @Override
    public void closed(long line, double duration, boolean discharged) {
        if (line != this.line) {
            return; // another instance's obligation, never judged: its end says nothing of the one judged
        }
        this.ended = true;
        this.duration = duration;
        this.discharged = discharged;
    }

    @Override
    void follow(PropertyChecker checker, LogRecord r, boolean in) {
        if (ended) {
            ended = false;
            c.deadlines.ended(c.now.run, response, r, duration, discharged);
            if (discharged && active != null && active.clause() == MonitorEvent.Clause.DEADLINE) {
                ended(r, "discharged", Double.NaN, label() + ": the response came in time; the deadline warning is"
                        + " over");
            } else if (active != null && active.clause() == MonitorEvent.Clause.DEADLINE && in) {
                active = null; // let go at a missed deadline (the checker's violation): the next one is judged afresh
            }
            current = null;
            told = NONE;
            pending = null;
            line = -1;
        }
        double elapsed = checker.elapsed(index);
        if (Double.isNaN(elapsed)) {
            judgedAt = Double.NaN;
            pending = null;
            line = -1;
            return;
        }
        if (pending == null || checker.pendingLine(index) != line) {
            line = checker.pendingLine(index);
            pending = triggers == null ? survival : survival.at(triggers.began(index, line));
            judgedAt = Double.NaN;
        }
        if (elapsed == judgedAt && current != null) {
            return; // judged at this elapsed time already: a deadline in ticks changes at the next tick only
        }
        judgedAt = elapsed;
        Deadline d = response.within();
        Survival s = pending;
        Survival.Estimate raw = s.estimate(elapsed, d.amount());
        c.deadlines.forecast(c.now.run, response, r, elapsed, raw, s);
        Survival.Estimate e = rule.calibrated(raw);
        current = e;
        int shown = shownCode(e);
        if (shown != told) {
            told = shown;
            c.events.accept(new MonitorEvent.ForecastChanged(r.time(), r.line(), null, r.clock(), c.now.run,
                    response.id(), e, d.unit().key));
        }
        if (active == null && c.forecastRule() && rule.warns(raw, elapsed, d.amount(), s, survival)) {
            // A bounded response has no value: the warning carries none, as its violation and its recovery do not.
            warn(new MonitorEvent.Warning(r.time(), r.line(), List.of(), null, c.now.pairs, r.clock(), c.now.run,
                    c.rule, null, reason(response, e, elapsed, s, rule), MonitorEvent.Clause.DEADLINE, null,
                    response.id(), e));
        }
    }

    @Override
    public void reset() {
        super.reset();
        current = null;
        told = NONE;
        ended = false;
        discharged = false;
        judgedAt = Double.NaN;
        pending = null;
        line = -1;
    }

    @Override
    public PropertyStatus status(PropertyChecker checker) {
        return new PropertyStatus(property, checker.verdict(index), PropertyStatus.Model.DEADLINE, warned(), current,
                response.within().unit().key);
    }

    /**
     * A deadline forecast as the page shows it: {@code novel} past every training obligation, else the probability
     * of a miss in whole percent ({@code <1%} and {@code >99%} at the ends, never 0% or 100% for what is not certain).
     */
    static String shown(Survival.Estimate e) {
        int code = shownCode(e);
        return code == NOVEL ? "novel" : code == BELOW_1 ? "<1%" : code == ABOVE_99 ? ">99%" : code + "%";
    }

    /**
     * {@link #shown} as a number, one per text it can be (the percent, {@link #NOVEL}, {@link #BELOW_1},
     * {@link #ABOVE_99}), so that the forecast judged at every record is compared without being written.
     */
    static int shownCode(Survival.Estimate e) {
        if (e.novel()) {
            return NOVEL;
        }
        double p = e.probability();
        long v = Math.round(p * 100);
        return p > 0 && v == 0 ? BELOW_1 : p < 1 && v == 100 ? ABOVE_99 : (int) v;
    }

    /**
     * In words: "pending 334 ticks, longer than any of the 38 training obligations (the longest: 268 ticks); 66
     * ticks left before the deadline of 400 ticks", or "pending 40 ticks; 2 of the 5 training obligations pending
     * that long took longer than 400 ticks; P(miss) 0.62; 20 ticks left".
     */
    static String reason(Response p, Survival.Estimate e, double elapsed, Survival s) {
        return reason(p, e, elapsed, s, DeadlineRule.DEFAULT);
    }

    /**
     * As above; when {@code rule}'s late clause warns: "pending 73 ticks, later than 99% of legs like the 10 training
     * obligations that began where it did (they took 4 to 25 ticks; late past 72); 327 ticks left before the
     * deadline of 400 ticks".
     */
    static String reason(Response p, Survival.Estimate e, double elapsed, Survival s, DeadlineRule rule) {
        Deadline d = p.within();
        String unit = d.unit().key;
        String head = String.format(Locale.ROOT, "'%s' (%s) pending %s %s", p.name(), p.id(),
                ForecastWords.fixed(elapsed, 0), unit);
        String action = p.action() == null ? "" : "; do now: " + p.action();
        if (rule.late() && !rule.baseline() && DeadlineRule.pastLate(elapsed, s, rule.level(), rule.waited())) {
            double[] took = s.discharged();
            return String.format(Locale.ROOT, "%s, later than %s of obligations like the %d training ones that began"
                            + " where it did (they took %s to %s %s; late past %s); %s %s left before the deadline of"
                            + " %s%s", head, DeadlineRule.percent(rule.level()), took.length,
                    ForecastWords.fixed(took[0], 0), ForecastWords.fixed(took[took.length - 1], 0), unit,
                    ForecastWords.fixed(s.lateAfter(rule.level(), rule.waited()), 0), ForecastWords.fixed(e.timeLeft(), 0), unit,
                    d.describe(), action);
        }
        if (e.novel()) {
            return String.format(Locale.ROOT, "%s, longer than any of the %d training obligations (the longest: %s):"
                            + " behaviour never seen; %s %s left before the deadline of %s%s", head, s.size(),
                    ForecastWords.fixed(s.longest(), 0), ForecastWords.fixed(e.timeLeft(), 0), unit, d.describe(),
                    action);
        }
        return String.format(Locale.ROOT, "%s; %d of the %d training obligations pending that long took longer than %s;"
                        + " P(miss) %s; %s %s left%s", head, e.longer(), e.atRisk(), d.describe(),
                ForecastWords.fixed(e.probability(), 2), ForecastWords.fixed(e.timeLeft(), 0), unit, action);
    }
}
