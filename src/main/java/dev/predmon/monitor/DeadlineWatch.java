package dev.predmon.monitor;

import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.forecast.Survival;
import dev.predmon.property.Deadline;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.Response;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;

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
 * that half of the margin left. A property without a training obligation gets no
 * forecast and no warning: no verdict on no evidence. Constant state per property.
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

    private final Response[] properties;
    private final Survival[] survival;
    private final DeadlineRule[] rules;
    private final boolean[] warned;

    /** The deadlines of {@code properties} that {@code model} learned durations for; none without a model. */
    DeadlineWatch(List<Property> properties, ForecastModel model) {
        this.properties = new Response[properties.size()];
        this.survival = new Survival[properties.size()];
        this.rules = new DeadlineRule[properties.size()];
        this.warned = new boolean[properties.size()];
        for (int i = 0; i < properties.size(); i++) {
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

    /** After {@code checker} took a record: tells {@code out} each deadline warning it raises. */
    void step(PropertyChecker checker, Consumer<Due> out) {
        for (int i = 0; i < properties.length; i++) {
            if (properties[i] == null) {
                continue;
            }
            double elapsed = checker.elapsed(i);
            if (Double.isNaN(elapsed)) {
                warned[i] = false; // the obligation was discharged or let go: the next one is judged afresh
                continue;
            }
            if (warned[i]) {
                continue;
            }
            Deadline d = properties[i].within();
            Survival s = survival[i];
            Survival.Estimate raw = s.estimate(elapsed, d.amount());
            if (rules[i].warns(raw, elapsed, d.amount(), s)) {
                Survival.Estimate e = rules[i].calibrated(raw);
                warned[i] = true;
                out.accept(new Due(properties[i], e, elapsed, reason(properties[i], e, elapsed, s)));
            }
        }
    }

    /** A new run. */
    void reset() {
        Arrays.fill(warned, false);
    }

    /**
     * In words: "pending 334 ticks, longer than any of the 38 training obligations (the longest: 268 ticks); 66
     * ticks left before the deadline of 400 ticks", or "pending 40 ticks; 2 of the 5 training obligations pending
     * that long took longer than 400 ticks; P(miss) 0.62; 20 ticks left".
     */
    static String reason(Response p, Survival.Estimate e, double elapsed, Survival s) {
        Deadline d = p.within();
        String unit = d.unit() == Deadline.Unit.OCCURRENCES ? "occurrences" : d.unit().key;
        String head = String.format(Locale.ROOT, "'%s' (%s) pending %s %s", p.name(), p.id(),
                ForecastWords.fixed(elapsed, 0), unit);
        if (e.novel()) {
            return String.format(Locale.ROOT, "%s, longer than any of the %d training obligations (the longest: %s):"
                            + " behaviour never seen; %s %s left before the deadline of %s", head, s.size(),
                    ForecastWords.fixed(s.longest(), 0), ForecastWords.fixed(e.timeLeft(), 0), unit, d.describe());
        }
        return String.format(Locale.ROOT, "%s; %d of the %d training obligations pending that long took longer than %s;"
                        + " P(miss) %s; %s %s left", head, e.longer(), e.atRisk(), d.describe(),
                ForecastWords.fixed(e.probability(), 2), ForecastWords.fixed(e.timeLeft(), 0), unit);
    }
}
