package dev.predmon.replay;

import dev.predmon.compact.IoPair;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.Survival;
import dev.predmon.matching.ModelTracker;
import dev.predmon.model.LearnedModel;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.property.Response;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

/**
 * One run of a replayed log, as the monitor took it.
 *
 * @param run       0, 1, ... in log order
 * @param outcome   the monitor's outcome of the run (its first warning and violation, its verdicts)
 * @param pairs     its compacted pairs, each with the record that completed it
 * @param gaps      the lines of the messages the abstraction could not name (the trace misses a step there)
 * @param forecasts every forecast the monitor made, one after each pair and each new value of the property, each
 *                  with the record that made it
 * @param forecastsBeforeViolation how many of {@code forecasts} came before the forecast property's first violation
 *                                 (all of them in a run that held)
 * @param events    every event the monitor told in the run, in order
 * @param models    every model as the monitor's matching left it at the run's end, in model order
 * @param matchRuleAt the pair after which the thesis's match rule first held ({@code confirm} included), or -1
 * @param obligations every obligation of a bounded response that the monitor forecast and that ended in the run (its
 *                    response came, or it was let go: its deadline passed or its scope closed), in the order they
 *                    ended; one still pending at the run's end has no outcome and is not among them
 * @param boundForecasts by id, every bound property with a value forecast of its own (not the forecast's property):
 *                  every forecast of it, one after each pair and each new value of it, as the property reads, each
 *                  with the record that made it
 * @param boundForecastsBeforeViolation by id, how many of {@code boundForecasts} came before the property's first
 *                  violation (absent in a run where it held)
 */
public record ReplayedRun(int run, RunOutcome outcome, List<Pair> pairs, List<Long> gaps, List<Timed> forecasts,
                          int forecastsBeforeViolation, List<MonitorEvent> events, List<Fate> models,
                          long matchRuleAt, List<Obligation> obligations, Map<String, List<Timed>> boundForecasts,
                          Map<String, Integer> boundForecastsBeforeViolation) {

    public ReplayedRun {
        obligations = List.copyOf(obligations);
        models = List.copyOf(models);
        pairs = List.copyOf(pairs);
        gaps = List.copyOf(gaps);
        forecasts = List.copyOf(forecasts);
        events = List.copyOf(events);
        Map<String, List<Timed>> copy = new TreeMap<>();
        boundForecasts.forEach((id, f) -> copy.put(id, List.copyOf(f)));
        boundForecasts = Collections.unmodifiableMap(copy);
        boundForecastsBeforeViolation = Map.copyOf(boundForecastsBeforeViolation);
    }

    /** The forecasts of bound property {@code id} made before its first violation: what its forecast is scored on. */
    public List<Timed> boundBeforeViolation(String id) {
        List<Timed> all = boundForecasts.getOrDefault(id, List.of());
        return all.subList(0, boundForecastsBeforeViolation.getOrDefault(id, all.size()));
    }

    /**
     * One model as the matching left it at the end of the run.
     *
     * @param matched          whether it still matched the run
     * @param discrepancies    outputs that differed up to its elimination or the end
     * @param elimination      where it stopped matching (an input it had no transition for, or the difference past
     *                         the threshold), null while it matches
     * @param firstDiscrepancy its first output that differed, or null
     */
    public record Fate(LearnedModel model, boolean matched, int discrepancies, ModelTracker.Failure elimination,
                       ModelTracker.Failure firstDiscrepancy) {

        static Fate of(ModelTracker t) {
            return new Fate(t.model(), t.alive(), t.discrepancies(), t.elimination(), t.firstDiscrepancy());
        }
    }

    /** A compacted pair and the record whose arrival completed it. */
    public record Pair(IoPair pair, double time, long line) {
    }

    /**
     * A forecast and the record that made it.
     *
     * @param pairs the run's pairs taken when it was made (a forecast after a pair counts that pair)
     */
    public record Timed(Forecast forecast, double time, long line, long pairs) {
    }

    /**
     * One obligation of a bounded response as the monitor forecast it ({@code DeadlineFollow}) and as it ended.
     *
     * @param property   the property
     * @param forecasts  every deadline forecast of it, raw (before the rule's calibration), in order: one at each
     *                   elapsed time the monitor judged it at
     * @param duration   how long it was pending, in its deadline's unit
     * @param discharged whether its response came; else it was let go still pending
     * @param time       the time of the record that ended it
     * @param line       that record's line
     * @param warnedAt   how long it had been pending when the monitor warned of its deadline, NaN when it did not
     * @param curve      the training obligations it was judged against (those that began where it did,
     *                   {@link Survival#at}), null when it had no forecast
     */
    public record Obligation(Response property, List<Step> forecasts, double duration, boolean discharged,
                             double time, long line, double warnedAt, Survival curve) {

        public Obligation {
            forecasts = List.copyOf(forecasts);
        }

        /** As above, its curve not known. */
        public Obligation(Response property, List<Step> forecasts, double duration, boolean discharged, double time,
                          long line, double warnedAt) {
            this(property, forecasts, duration, discharged, time, line, warnedAt, null);
        }

        /** Whether it was let go past its deadline: the deadline was missed (the property's violation). */
        public boolean missed() {
            return !discharged && duration > property.within().amount();
        }
    }

    /**
     * A deadline forecast and the record that made it.
     *
     * @param estimate the raw estimate
     * @param elapsed  how long the obligation had been pending, in its deadline's unit
     */
    public record Step(Survival.Estimate estimate, double elapsed, double time, long line) {
    }

    /** The forecasts made before the forecast property's first violation: what a forecast is scored on. */
    public List<Timed> beforeViolation() {
        return forecasts.subList(0, forecastsBeforeViolation);
    }

    /** Whether the forecast property was violated in the run. */
    public boolean violated() {
        return outcome.violation() != null;
    }

    /** The run's warnings, in order (the first is the outcome's; later ones follow a recovery or are a deadline's). */
    public List<MonitorEvent.Warning> warnings() {
        return events.stream().filter(MonitorEvent.Warning.class::isInstance).map(MonitorEvent.Warning.class::cast)
                .toList();
    }

    /** The forecast right after each pair, in pair order (empty without a forecast). */
    public List<Forecast> afterPairs() {
        List<Forecast> out = new ArrayList<>();
        for (Timed t : forecasts) {
            if (t.pairs() > out.size()) {
                out.add(t.forecast()); // the first forecast once a pair came is the one after it
            }
        }
        return List.copyOf(out);
    }

    /** The run's first event of {@code type}, if any. */
    public <E extends MonitorEvent> Optional<E> first(Class<E> type) {
        return events.stream().filter(type::isInstance).map(type::cast).findFirst();
    }
}
