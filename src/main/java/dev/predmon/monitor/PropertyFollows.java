package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.compact.IoPair;
import dev.predmon.forecast.BoundModel;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.forecast.Survival;
import dev.predmon.matching.Matching;
import dev.predmon.model.ModelIndex;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.LogRecord;
import dev.predmon.pipeline.TriggerInputs;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.Response;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Every property of the abstraction followed through the runs of one log: one {@link PropertyChecker} judges them
 * all on every record, and one {@link PropertyFollow} per property, in the abstraction's order, turns its judgement
 * into the property's events. Which follower a property gets depends only on its kind and on what the models learned
 * of it: a bound its value forecast ({@link BoundFollow}), a bounded response its deadline forecast
 * ({@link DeadlineFollow}), an absence or a precedence its event forecast ({@link EventFollow}), any other a check
 * ({@link CheckedFollow}).
 *
 * <p>Beside the properties' own forecasts, the thesis's matching warns once a run when every nominal model is
 * eliminated while a faulty one still matches: of the property the likeliest faulty scenario's {@code scenario.json}
 * says it violates, else of the headline property.
 */
final class PropertyFollows {

    private final PropertyChecker checker;
    /** Typed by their common base, not the interface: one call per property and record, bound without a lookup. */
    private final FollowBase[] follows;
    private final FollowContext c;
    /** The headline property's follower, or null without one. */
    private final BoundFollow headline;
    /** By faulty scenario, the position of the property its runs violate, when its {@code scenario.json} names one. */
    private final Map<String, Integer> violates;
    private boolean matchingSpent;
    /** Where each bounded response's obligation began, for its deadline forecast; null without one. */
    private final TriggerInputs triggers;
    /** Whether the cross-validation kept the matching clause (it warns on its own only where it earned its place). */
    private final boolean matchingWarns;

    /** Every property of {@code abstraction}, forecast as {@code models} learned them. */
    PropertyFollows(ModelSet models, Abstraction abstraction, FollowContext c) {
        this(models, abstraction, abstraction.properties(), c);
    }

    /** Every one of {@code properties}, forecast as {@code models} learned them, each deadline by its pooled curve. */
    PropertyFollows(ModelSet models, List<Property> properties, FollowContext c) {
        this(models, null, properties, c);
    }

    private PropertyFollows(ModelSet models, Abstraction abstraction, List<Property> properties, FollowContext c) {
        this.c = c;
        this.checker = new PropertyChecker(properties, (i, p, v) -> { });
        this.follows = new FollowBase[properties.size()];
        ForecastModel forecast = models.forecast();
        BoundFollow head = null;
        TriggerInputs began = null;
        for (int i = 0; i < follows.length; i++) {
            Property p = properties.get(i);
            if (p instanceof Bound b) {
                BoundModel m = BoundModel.of(forecast, b.id(), c.headline);
                BoundFollow f = new BoundFollow(i, b, m, models.machines(), c);
                head = b.id().equals(c.headline) ? f : head;
                follows[i] = f;
            } else if (p instanceof Response r && forecast != null && forecast.obligations().get(r.id()) != null
                    && forecast.obligations().get(r.id()).size() > 0) {
                Survival s = forecast.obligations().get(r.id());
                began = began != null || abstraction == null ? began : new TriggerInputs(abstraction, properties);
                follows[i] = new DeadlineFollow(i, r, s, forecast.deadlineRule(r.id()), began, c);
            } else if (forecast != null && forecast.events().get(p.id()) != null) {
                follows[i] = new EventFollow(i, p, forecast.events().get(p.id()), models.machines(), c);
            } else {
                follows[i] = new CheckedFollow(i, p, c);
            }
        }
        this.headline = head;
        this.triggers = began;
        this.matchingWarns = forecast == null || forecast.matchingWarns();
        checker.onObligations((index, p, line, duration, discharged) -> {
            if (triggers != null) {
                triggers.closed(index, line);
            }
            follows[index].closed(line, duration, discharged);
        });
        this.violates = violates(models, properties);
    }

    /** Takes {@code r}, the next record of the run: every property's events at it. */
    void record(LogRecord r) {
        checker.accept(r);
        if (triggers != null) {
            triggers.record(checker, r);
        }
        for (FollowBase f : follows) {
            f.record(checker, r);
        }
    }

    /** A compacted pair: every forecast after it, then the matching's warning, then the forecasts' own warnings. */
    void pair(IoPair pair, Matching.Step step, LogRecord trigger) {
        for (FollowBase f : follows) {
            f.pair(pair, step, trigger);
        }
        matching(step, trigger);
        for (FollowBase f : follows) {
            f.decide(pair, step, trigger);
        }
    }

    /** A gap in the trace at {@code line}. */
    void gap(long line) {
        for (FollowBase f : follows) {
            f.gap(line);
        }
    }

    /**
     * The run ends, {@code first} beginning the next: a deadline that passed before it came is violated there, in
     * the run that ends ({@link PropertyChecker#overdue}), and told.
     */
    void ending(LogRecord first) {
        checker.overdue(first);
        for (FollowBase f : follows) {
            f.overdue(checker, first);
        }
    }

    /** The run ended at {@code last} ({@code why}): every alarm still up ends. */
    void runEnded(LogRecord last, String why) {
        if (last == null) {
            return;
        }
        for (FollowBase f : follows) {
            f.runEnded(last, why);
        }
    }

    /** A new run: every property starts over. */
    void reset() {
        checker.reset();
        if (triggers != null) {
            triggers.reset();
        }
        matchingSpent = false;
        for (FollowBase f : follows) {
            f.reset();
        }
    }

    void countTicksAs(TickSeconds t) {
        checker.countTicksAs(t.seconds());
        for (FollowBase f : follows) {
            f.countTicksAs(t);
        }
    }

    /** The headline property's follower, or null. */
    BoundFollow headline() {
        return headline;
    }

    /** Every property with its verdict on the current run so far. */
    List<PropertyChecker.PropertyVerdict> verdicts() {
        return checker.verdicts();
    }

    /** Every property now, in the abstraction's order. */
    List<PropertyStatus> statuses() {
        List<PropertyStatus> all = new ArrayList<>(follows.length);
        for (FollowBase f : follows) {
            all.add(f.status(checker));
        }
        return all;
    }

    /** The value property {@code id} read at the last record, whatever its scope; NaN without one (or no bound). */
    double value(String id) {
        for (int i = 0; i < follows.length; i++) {
            if (checker.properties().get(i).id().equals(id)) {
                return checker.value(i);
            }
        }
        return Double.NaN;
    }

    /** The checker of the run (read-only use: the judge of every property). */
    PropertyChecker checker() {
        return checker;
    }

    /**
     * The thesis's verdict after a pair, once a run: every nominal model eliminated while a faulty one still matches
     * ({@code confirm} pairs on). Under the forecast rule it is taken only when every nominal model was contradicted
     * while the run does what the models know ({@link ForecastTracker#takesMatching}, on the headline's forecast).
     */
    private void matching(Matching.Step step, LogRecord trigger) {
        if (!step.ruleWarns() || matchingSpent) {
            return;
        }
        Forecast f = headline == null ? null : headline.last();
        if (c.forecastRule() && (!matchingWarns || !ForecastTracker.takesMatching(f, step))) {
            return;
        }
        String scenario = c.likeliestFaulty(step.faultyAlive());
        Integer at = scenario == null ? null : violates.get(scenario);
        PropertyFollow target = at != null ? follows[at] : headline;
        if (target != null && !target.takesMatching()) {
            return;
        }
        String reason = MonitorEvent.Warning.onlyFaulty(step.faultyAlive()) + (f == null ? "" : "; "
                + ForecastWords.line(f));
        String about = c.headline;
        if (at != null && target != headline) {
            Property p = checker.properties().get(at);
            about = p.id();
            reason = "'" + p.name() + "' (" + p.id() + "), which faulty scenario " + scenario + " violates: " + reason;
        }
        MonitorEvent.Warning w = new MonitorEvent.Warning(trigger.time(), trigger.line(), step.faultyAlive(),
                target == null ? null : target.value(), c.now.pairs, trigger.clock(), c.now.run, c.rule, f, reason,
                MonitorEvent.Clause.MATCHING, scenario, about);
        matchingSpent = true;
        if (target != null) {
            target.matchingWarned(w);
        }
        c.events.accept(w);
    }

    private static Map<String, Integer> violates(ModelSet models, List<Property> properties) {
        Map<String, Integer> out = new HashMap<>();
        for (ModelIndex.Scenario s : models.index().scenarios()) {
            for (int i = 0; s.faulty() && s.violates() != null && i < properties.size(); i++) {
                if (properties.get(i).id().equals(s.violates())) {
                    out.putIfAbsent(s.name(), i);
                }
            }
        }
        return out;
    }
}
