package dev.predmon.monitor;

import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.forecast.Survival;
import dev.predmon.parse.LogRecord;
import dev.predmon.pipeline.TriggerInputs;
import dev.predmon.property.Deadline;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.Response;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * The deadline forecast of every bounded-response property the models learned durations for: while an obligation is
 * pending, how likely it is to miss its deadline given how long it has been pending, against how long the training
 * runs' obligations of the same property took ({@link Survival}, Kaplan-Meier with the runs that stopped early
 * censored).
 *
 * <p>It warns once per obligation, by the property's {@link DeadlineRule}: when the calibrated P(miss) reaches the
 * threshold learned by cross-validation (even odds when the training obligations could not choose one), or when the
 * obligation has been pending longer than every training obligation (no evidence either way) and half of the time
 * from the longest of them to the deadline has passed too: a robot stuck in a way no training run was is warned with
 * that half of the margin left. A warned obligation that is discharged in time ends its warning
 * ({@link Listener#recovered}); one that misses its deadline is the property's violation, told by the checker. While
 * an obligation is pending its (calibrated) forecast is told when it changes as the page shows it: the probability of
 * a miss in whole percent, or that the obligation is past every training one. A property without a training
 * obligation gets no forecast and no warning: no verdict on no evidence. Constant state per property.
 */
final class DeadlineWatch {

    /**
     * A deadline warning.
     *
     * @param property the property
     * @param estimate the forecast that warned
     * @param elapsed  how long the obligation has been pending, in its deadline's unit
     * @param reason   why, in an operator's words
     */
    record Due(Response property, Survival.Estimate estimate, double elapsed, String reason) {
    }

    /** Told what the deadline forecasts say, as it happens, with the record that made it. */
    interface Listener {
        /** A deadline warning. */
        void due(LogRecord r, Due d);

        /** The warned obligation of {@code property} was discharged in time: the warning's cause ended. */
        void recovered(LogRecord r, Response property, String reason);

        /** The forecast of {@code property}'s pending obligation changed as shown. */
        void changed(LogRecord r, Response property, Survival.Estimate estimate);

        /**
         * {@code property}'s pending obligation was judged at {@code r}, pending for {@code elapsed} (in its deadline's
         * unit): {@code raw} is the estimate before the rule's calibration. Told at every judgement, before what it
         * changes and warns.
         */
        default void judged(LogRecord r, Response property, double elapsed, Survival.Estimate raw) {
        }

        /**
         * An obligation of {@code property} ended at {@code r} after {@code duration} (in its deadline's unit):
         * {@code discharged}, or let go still pending (its deadline passed, or its scope closed).
         */
        default void ended(LogRecord r, Response property, double duration, boolean discharged) {
        }
    }

    private final Response[] properties;
    private final Survival[] survival;
    private final DeadlineRule[] rules;
    private final boolean[] warned;
    /** The forecast of each obligation pending now, or null. */
    private final Survival.Estimate[] current;
    /** Each pending obligation's forecast as last told ({@link #shown}), or null. */
    private final String[] told;
    /** Whether an obligation of each property ended at the last record, and whether it was discharged. */
    private final boolean[] ended;
    private final boolean[] discharged;
    /** How long the obligation that ended at the last record was pending. */
    private final double[] durations;
    /** Each pending obligation's elapsed time when it was last judged, NaN before. */
    private final double[] judgedAt;
    /**
     * The curve each pending obligation is judged by: its trigger input's own ({@link Survival#at}), else the pooled
     * one; null while none is pending.
     */
    private final Survival[] pending;
    /** Where each obligation began (null: judged by the pooled curves alone). */
    private final TriggerInputs triggers;

    /** The deadlines of {@code properties} that {@code model} learned durations for, by the pooled curves alone. */
    DeadlineWatch(List<Property> properties, ForecastModel model) {
        this(properties, model, null);
    }

    /**
     * The deadlines of {@code properties} that {@code model} learned durations for; none without a model. Each
     * obligation is judged by the curve of where it began ({@code triggers}, {@link Survival#at}) when the model has
     * one.
     */
    DeadlineWatch(List<Property> properties, ForecastModel model, TriggerInputs triggers) {
        this.triggers = triggers;
        this.pending = new Survival[properties.size()];
        int n = properties.size();
        this.properties = new Response[n];
        this.survival = new Survival[n];
        this.rules = new DeadlineRule[n];
        this.warned = new boolean[n];
        this.current = new Survival.Estimate[n];
        this.told = new String[n];
        this.ended = new boolean[n];
        this.discharged = new boolean[n];
        this.durations = new double[n];
        this.judgedAt = new double[n];
        Arrays.fill(judgedAt, Double.NaN);
        for (int i = 0; i < n; i++) {
            if (properties.get(i) instanceof Response r && model != null) {
                Survival s = model.obligations().get(r.id());
                if (s != null && s.size() > 0) {
                    this.properties[i] = r;
                    this.survival[i] = s;
                    this.rules[i] = model.deadlineRule(r.id());
                }
            }
        }
    }

    /** Whether property {@code index} has a deadline forecast. */
    boolean forecasts(int index) {
        return properties[index] != null;
    }

    /** The forecast of property {@code index}'s pending obligation, or null when none is pending (or no forecast). */
    Survival.Estimate current(int index) {
        return current[index];
    }

    /** Whether a warning of property {@code index} is up. */
    boolean warned(int index) {
        return warned[index];
    }

    /**
     * An obligation of property {@code index} ended after {@code duration}, {@code discharged} or let go (as the
     * checker tells it).
     */
    void closed(int index, double duration, boolean discharged) {
        if (triggers != null) {
            triggers.closed(index);
        }
        this.ended[index] = true;
        this.durations[index] = duration;
        this.discharged[index] = discharged;
    }

    /** After {@code checker} took a record: tells {@code out} each warning, recovery and forecast it makes. */
    void step(PropertyChecker checker, LogRecord r, Listener out) {
        if (triggers != null) {
            triggers.record(checker, r);
        }
        for (int i = 0; i < properties.length; i++) {
            if (properties[i] == null) {
                continue;
            }
            if (ended[i]) {
                ended[i] = false;
                out.ended(r, properties[i], durations[i], discharged[i]);
                if (warned[i] && discharged[i]) {
                    out.recovered(r, properties[i], "'" + properties[i].name() + "' (" + properties[i].id()
                            + "): the response came in time; the deadline warning is over");
                }
                // discharged, or let go at a missed deadline (the checker's violation): the next one is judged afresh
                warned[i] = false;
                current[i] = null;
                told[i] = null;
                pending[i] = null;
            }
            double elapsed = checker.elapsed(i);
            if (Double.isNaN(elapsed)) {
                judgedAt[i] = Double.NaN;
                pending[i] = null;
                continue;
            }
            if (pending[i] == null) {
                pending[i] = triggers == null ? survival[i] : survival[i].at(triggers.began(i));
            }
            if (elapsed == judgedAt[i] && current[i] != null) {
                continue; // judged at this elapsed time already: a deadline in ticks changes at the next tick only
            }
            judgedAt[i] = elapsed;
            Deadline d = properties[i].within();
            Survival s = pending[i];
            Survival.Estimate raw = s.estimate(elapsed, d.amount());
            out.judged(r, properties[i], elapsed, raw);
            Survival.Estimate e = rules[i].calibrated(raw);
            current[i] = e;
            String shown = shown(e);
            if (!shown.equals(told[i])) {
                told[i] = shown;
                out.changed(r, properties[i], e);
            }
            if (warned[i]) {
                continue;
            }
            if (rules[i].warns(raw, elapsed, d.amount(), s, survival[i])) {
                warned[i] = true;
                out.due(r, new Due(properties[i], e, elapsed, reason(properties[i], e, elapsed, s)));
            }
        }
    }

    /** A new run. */
    void reset() {
        Arrays.fill(warned, false);
        Arrays.fill(current, null);
        Arrays.fill(told, null);
        Arrays.fill(ended, false);
        Arrays.fill(discharged, false);
        Arrays.fill(judgedAt, Double.NaN);
        Arrays.fill(pending, null);
        if (triggers != null) {
            triggers.reset();
        }
    }

    /**
     * A deadline forecast as the page shows it: {@code novel} past every training obligation, else the probability
     * of a miss in whole percent ({@code <1%} and {@code >99%} at the ends, never 0% or 100% for what is not certain).
     */
    static String shown(Survival.Estimate e) {
        if (e.novel()) {
            return "novel";
        }
        double p = e.probability();
        long v = Math.round(p * 100);
        return p > 0 && v == 0 ? "<1%" : p < 1 && v == 100 ? ">99%" : v + "%";
    }

    /**
     * In words: "pending 334 ticks, longer than any of the 38 training obligations (the longest: 268 ticks); 66
     * ticks left before the deadline of 400 ticks", or "pending 40 ticks; 2 of the 5 training obligations pending
     * that long took longer than 400 ticks; P(miss) 0.62; 20 ticks left".
     */
    static String reason(Response p, Survival.Estimate e, double elapsed, Survival s) {
        Deadline d = p.within();
        String unit = d.unit().key;
        String head = String.format(Locale.ROOT, "'%s' (%s) pending %s %s", p.name(), p.id(),
                ForecastWords.fixed(elapsed, 0), unit);
        String action = p.action() == null ? "" : "; do now: " + p.action();
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
