package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.Forecast;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Bound;
import dev.predmon.property.Deadline;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.Response;
import dev.predmon.property.Verdict;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

/**
 * The safety monitor of one log: checks every property of the abstraction on every run ({@link PropertyChecker}) for
 * its verdict, and tells each property's first violation in a run as a {@link MonitorEvent.Violation} naming it, but
 * for the forecast's property ({@link Abstraction#safety()}): {@link PredictiveMonitor} tells that one's violations
 * itself, with the alarm that follows it (violated, recovered, violated again).
 */
final class SafetyMonitor {

    private final PropertyChecker checker;
    /** The forecast property's position among the checked ones, or -1 without one. */
    private final int forecastIndex;
    private final String forecastId;
    private final Consumer<MonitorEvent> events;
    private LogRecord record;
    private int run;
    /** The deadline forecasts, or null when nothing warns by them (the match rule, models without a forecast). */
    private final DeadlineWatch deadlines;
    private final DeadlineWatch.Listener told;
    /** The other bound properties' value forecasts, or null when nothing warns by them. */
    private BoundWatch bounds;
    /** Whether no nominal model matches the run any more (what the bounds' novelty clause asks). */
    private BooleanSupplier beyondNominal = () -> false;

    SafetyMonitor(Abstraction abstraction, Consumer<MonitorEvent> events) {
        this(abstraction, events, null, null);
    }

    /**
     * Also forecasts the bound properties other than the forecast's by {@code bounds}, {@code beyondNominal} telling
     * whether no nominal model matches the run any more; returns {@code bounds}.
     */
    BoundWatch forecastBounds(BoundWatch bounds, BooleanSupplier beyondNominal) {
        this.bounds = bounds;
        this.beyondNominal = beyondNominal;
        return bounds;
    }

    /** Reports the other bound properties' forecast times in seconds, a tick lasting {@code t}. */
    void countTicksAs(TickSeconds t) {
        checker.countTicksAs(t.seconds());
        if (bounds != null) {
            bounds.countTicksAs(t);
        }
    }

    /** As above, telling {@code told} what the deadline forecasts of {@code deadlines} say. */
    SafetyMonitor(Abstraction abstraction, Consumer<MonitorEvent> events, DeadlineWatch deadlines,
                  DeadlineWatch.Listener told) {
        this.deadlines = deadlines;
        this.told = told;
        Optional<Bound> forecast = abstraction.safety();
        this.forecastIndex = forecast.map(b -> abstraction.properties().indexOf(b)).orElse(-1);
        this.forecastId = forecast.map(Bound::id).orElse(null);
        this.checker = new PropertyChecker(abstraction.properties(), this::violated);
        if (deadlines != null) {
            checker.onObligations((index, p, duration, discharged) -> deadlines.closed(index, duration, discharged));
        }
        this.events = events;
    }

    /** Checks {@code r}, the next record of run {@code run}, telling the violations it makes. */
    void accept(LogRecord r, int run) {
        this.record = r;
        this.run = run;
        checker.accept(r);
        if (deadlines != null) {
            deadlines.step(checker, r, told);
        }
        if (bounds != null) {
            bounds.record(checker, r, beyondNominal.getAsBoolean());
        }
    }

    private void violated(int index, Property p, Verdict.Violated v) {
        if (index != forecastIndex) {
            events.accept(new MonitorEvent.Violation(v.time(), v.line(), p.id(), p.name(), v.value(), v.before(),
                    v.what(), record.clock(), run, false));
        }
    }

    /**
     * Run {@code run} ends, {@code first} beginning the next: a deadline that passed before it came is violated there,
     * in run {@code run} ({@link PropertyChecker#overdue}).
     */
    void ending(LogRecord first, int run) {
        this.record = first;
        this.run = run;
        checker.overdue(first);
    }

    /** A new run: every property starts over. */
    void reset() {
        checker.reset();
        if (deadlines != null) {
            deadlines.reset();
        }
        if (bounds != null) {
            bounds.reset();
        }
    }

    /**
     * The forecast property's value on the record last checked ({@link Bound#valueOf}, whatever its scope), read once
     * by the checker; NaN when the record carried none or there is no such property.
     */
    double forecastValue() {
        return forecastIndex < 0 ? Double.NaN : checker.value(forecastIndex);
    }

    /** The id of the property the forecast and the warnings are about, or null without one. */
    String forecastId() {
        return forecastId;
    }

    /** Every property with its verdict on the current run so far. */
    List<PropertyChecker.PropertyVerdict> verdicts() {
        return checker.verdicts();
    }

    /**
     * Every property now, in the abstraction's order: its verdict, what forecasts it, and for a deadline whether it
     * warned and the pending obligation's forecast.
     *
     * @param forecastWarned whether a warning of the forecast's property is up
     * @param forecastNow    the forecast's property's latest forecast, or null
     * @param matchingWarned the other properties the matching warned of in the run (a faulty scenario's
     *                       {@code violates})
     */
    List<PropertyStatus> statuses(boolean forecastWarned, Forecast forecastNow, Set<String> matchingWarned) {
        List<PropertyStatus> all = new ArrayList<>(checker.properties().size());
        for (int i = 0; i < checker.properties().size(); i++) {
            Property p = checker.properties().get(i);
            Verdict v = checker.verdict(i);
            if (i == forecastIndex) {
                all.add(new PropertyStatus(p, v, PropertyStatus.Model.FORECAST, forecastWarned, null, null,
                        forecastNow));
            } else if (bounds != null && bounds.forecasts(i)) {
                all.add(new PropertyStatus(p, v, PropertyStatus.Model.FORECAST,
                        (bounds.warned(i) || matchingWarned.contains(p.id())) && !(v instanceof Verdict.Violated),
                        null, null, bounds.current(i)));
            } else if (deadlines != null && deadlines.forecasts(i)) {
                Deadline d = ((Response) p).within();
                all.add(new PropertyStatus(p, v, PropertyStatus.Model.DEADLINE,
                        (deadlines.warned(i) || matchingWarned.contains(p.id())) && !(v instanceof Verdict.Violated),
                        deadlines.current(i), d.unit().key));
            } else {
                all.add(new PropertyStatus(p, v, PropertyStatus.Model.NONE,
                        matchingWarned.contains(p.id()) && !(v instanceof Verdict.Violated), null, null));
            }
        }
        return all;
    }
}
