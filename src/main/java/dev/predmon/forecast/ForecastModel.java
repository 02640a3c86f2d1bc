package dev.predmon.forecast;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.TreeMap;

/**
 * Everything the forecast learned from the training runs, stored beside the machines ({@code forecast.json}).
 *
 * @param format      file format version, {@value #FORMAT}
 * @param unit        what the times count: {@code s}, or {@code ticks} for logs without time stamps
 * @param limit       the safety property's threshold (the property holds while the value is at least this), NaN
 *                    without a property
 * @param runs        training runs
 * @param violating   how many of them violated the property
 * @param lows        how low every training run went while safe, by outcome (runs without a reading left out)
 * @param threshold   the probability at or above which the forecast rule warns, chosen by cross-validation over the
 *                    training runs ({@link ThresholdChoice})
 * @param thresholdNote how it was chosen, in one line
 * @param validated   whether held-out runs of both outcomes chose the threshold (else it is a default, and the
 *                    forecast rule is not the default rule)
 * @param states      by machine id, by state number: what the runs did from there
 * @param startInputs the inputs the training runs began with: where the tree starts over
 * @param calibration the map from the per-state tables' estimate to the probability reported, fitted on the same
 *                    held-out runs as the threshold ({@link Calibration#IDENTITY} when none was fitted); the
 *                    threshold is on the calibrated scale
 * @param scorecards  how well the forecast did in that cross-validation, per property (empty when it did not run)
 * @param obligations by bounded-response property id, how long its obligations stayed pending in the training runs:
 *                    the deadline forecast of that property ({@link Survival})
 * @param deadlines   by bounded-response property id, when its deadline forecast warns, chosen by cross-validation
 *                    over those obligations; a property without one has {@link DeadlineRule#DEFAULT}
 * @param bounds      by id, every bound property but the one of {@code limit} (the abstraction's safety property): its
 *                    own value forecast, learned as this one is from the runs labelled by its own violation
 *                    ({@link BoundModel})
 * @param clauses     which parts of the rule warn, as the cross-validation chose them ({@link Clauses#ALL} in models
 *                    learned before the choice)
 * @param events      by id, every absence and precedence of the abstraction: the forecast of its event coming in
 *                    the rest of the run, or why the training runs cannot give one ({@link EventModel}); empty in
 *                    models learned before it
 * @param deadlineCards by bounded-response property id, the scorecard of its deadline forecast (a property without a
 *                    missed held-out deadline has none)
 * @param first       the id of the property the top-level fields forecast, the abstraction's first floor; null when it
 *                    has none, or when the model was read from a file of format 1, which does not name it
 * @param order       the properties' ids in the abstraction's order, the order {@code forecast.json} lists them in
 *                    (empty when not known: then the first floor, then by id)
 */
public record ForecastModel(int format, String unit, double limit, int runs, int violating, Lows lows,
                            double threshold, String thresholdNote, boolean validated,
                            Map<String, Map<Integer, StateStats>> states, List<String> startInputs,
                            Calibration calibration, List<Scorecard> scorecards,
                            Map<String, Survival> obligations, Map<String, DeadlineRule> deadlines,
                            Map<String, BoundModel> bounds, Clauses clauses, Map<String, EventModel> events,
                            Map<String, List<Scorecard>> deadlineCards, String first, List<String> order) {

    /** The format {@code forecast.json} is written in: one entry per property. */
    public static final int FORMAT = 2;
    /** The first format: the first floor at the top level, the other properties in side maps; still read. */
    public static final int FORMAT_1 = 1;

    /** The strength of the prior, in runs: a state seen by two runs moves the estimate only half way. */
    public static final double PRIOR_RUNS = 2.0;

    public ForecastModel {
        lows = lows.smoothed(PRIOR_RUNS, baseRate(runs, violating));
        states = Map.copyOf(states);
        startInputs = List.copyOf(startInputs);
        scorecards = List.copyOf(scorecards);
        obligations = Map.copyOf(obligations);
        deadlines = Map.copyOf(deadlines);
        bounds = Map.copyOf(bounds);
        events = Map.copyOf(events);
        deadlineCards = Map.copyOf(deadlineCards);
        order = List.copyOf(order);
        if (clauses == null) {
            throw new IllegalArgumentException("a forecast model needs its clauses");
        }
    }

    /** A model whose properties are not named (a model of the first floor and side maps, as format 1 holds it). */
    public ForecastModel(int format, String unit, double limit, int runs, int violating, Lows lows,
                         double threshold, String thresholdNote, boolean validated,
                         Map<String, Map<Integer, StateStats>> states, List<String> startInputs,
                         Calibration calibration, List<Scorecard> scorecards,
                         Map<String, Survival> obligations, Map<String, DeadlineRule> deadlines,
                         Map<String, BoundModel> bounds, Clauses clauses, Map<String, EventModel> events) {
        this(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated, states, startInputs,
                calibration, scorecards, obligations, deadlines, bounds, clauses, events, Map.of(), null, List.of());
    }

    /** A model without forecasts of absences and precedences. */
    public ForecastModel(int format, String unit, double limit, int runs, int violating, Lows lows,
                         double threshold, String thresholdNote, boolean validated,
                         Map<String, Map<Integer, StateStats>> states, List<String> startInputs,
                         Calibration calibration, List<Scorecard> scorecards,
                         Map<String, Survival> obligations, Map<String, DeadlineRule> deadlines,
                         Map<String, BoundModel> bounds, Clauses clauses) {
        this(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated, states, startInputs,
                calibration, scorecards, obligations, deadlines, bounds, clauses, Map.of());
    }

    /** This model with {@code forecasts} as the absences' and precedences' forecasts, by property id. */
    public ForecastModel withEvents(Map<String, EventModel> forecasts) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated,
                states, startInputs, calibration, scorecards, obligations, deadlines, bounds, clauses, forecasts,
                deadlineCards, first, order);
    }

    /** A model that warns by every clause of the forecast's rule. */
    public ForecastModel(int format, String unit, double limit, int runs, int violating, Lows lows,
                         double threshold, String thresholdNote, boolean validated,
                         Map<String, Map<Integer, StateStats>> states, List<String> startInputs,
                         Calibration calibration, List<Scorecard> scorecards,
                         Map<String, Survival> obligations, Map<String, DeadlineRule> deadlines,
                         Map<String, BoundModel> bounds) {
        this(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated, states, startInputs,
                calibration, scorecards, obligations, deadlines, bounds, Clauses.ALL);
    }

    /** This model warning by {@code c}. */
    public ForecastModel withClauses(Clauses c) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated,
                states, startInputs, calibration, scorecards, obligations, deadlines, bounds, c, events,
                deadlineCards, first, order);
    }

    /** A model without other bound properties' forecasts. */
    public ForecastModel(int format, String unit, double limit, int runs, int violating, Lows lows,
                         double threshold, String thresholdNote, boolean validated,
                         Map<String, Map<Integer, StateStats>> states, List<String> startInputs,
                         Calibration calibration, List<Scorecard> scorecards,
                         Map<String, Survival> obligations, Map<String, DeadlineRule> deadlines) {
        this(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated, states, startInputs,
                calibration, scorecards, obligations, deadlines, Map.of());
    }

    /** Every property's scorecard: this model's, then each deadline's, each other bound's and each event's, by id. */
    public List<Scorecard> allScorecards() {
        List<Scorecard> all = new ArrayList<>(scorecards);
        new TreeMap<>(deadlineCards).values().forEach(all::addAll);
        new TreeMap<>(bounds).values().forEach(b -> all.addAll(b.model().scorecards()));
        new TreeMap<>(events).values().forEach(e -> all.addAll(e.scorecards()));
        return List.copyOf(all);
    }

    /** This model with {@code forecasts} as the other bound properties' forecasts, by property id. */
    public ForecastModel withBounds(Map<String, BoundModel> forecasts) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated,
                states, startInputs, calibration, scorecards, obligations, deadlines, forecasts, clauses, events,
                deadlineCards, first, order);
    }

    /** A model whose deadline forecasts warn by the default rule. */
    public ForecastModel(int format, String unit, double limit, int runs, int violating, Lows lows, double threshold,
                         String thresholdNote, boolean validated, Map<String, Map<Integer, StateStats>> states,
                         List<String> startInputs, Calibration calibration, List<Scorecard> scorecards,
                         Map<String, Survival> obligations) {
        this(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated, states, startInputs,
                calibration, scorecards, obligations, Map.of());
    }

    /** When the deadline forecast of property {@code id} warns: its learned rule, else the default. */
    public DeadlineRule deadlineRule(String id) {
        return deadlines.getOrDefault(id, DeadlineRule.DEFAULT);
    }

    /** This model with {@code rules} as its deadline rules, by property id. */
    public ForecastModel withDeadlines(Map<String, DeadlineRule> rules) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated,
                states, startInputs, calibration, scorecards, obligations, rules, bounds, clauses, events,
                deadlineCards, first, order);
    }

    /** This model with {@code training} as its obligations, by property id. */
    public ForecastModel withObligations(Map<String, Survival> training) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated,
                states, startInputs, calibration, scorecards, training, deadlines, bounds, clauses, events,
                deadlineCards, first, order);
    }

    /** A model without deadline forecasts. */
    public ForecastModel(int format, String unit, double limit, int runs, int violating, Lows lows, double threshold,
                         String thresholdNote, boolean validated, Map<String, Map<Integer, StateStats>> states,
                         List<String> startInputs, Calibration calibration, List<Scorecard> scorecards) {
        this(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated, states, startInputs,
                calibration, scorecards, Map.of());
    }

    /** A model without a scorecard. */
    public ForecastModel(int format, String unit, double limit, int runs, int violating, Lows lows, double threshold,
                         String thresholdNote, boolean validated, Map<String, Map<Integer, StateStats>> states,
                         List<String> startInputs, Calibration calibration) {
        this(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated, states, startInputs,
                calibration, List.of());
    }

    /** A model whose probabilities are reported as the tables estimate them. */
    public ForecastModel(int format, String unit, double limit, int runs, int violating, Lows lows, double threshold,
                         String thresholdNote, boolean validated, Map<String, Map<Integer, StateStats>> states,
                         List<String> startInputs) {
        this(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated, states, startInputs,
                Calibration.IDENTITY);
    }

    /** The share of training runs that violated, with the prior of a fair coin of {@link #PRIOR_RUNS} runs. */
    public double baseRate() {
        return baseRate(runs, violating);
    }

    private static double baseRate(int runs, int violating) {
        return (violating + PRIOR_RUNS / 2) / (runs + PRIOR_RUNS);
    }

    /**
     * P(violation | the property now reads {@code value}): of the training runs that went as low as {@code value}
     * while safe, the share that went on to violate, smoothed towards the base rate. The value table needs no
     * machine, so it answers through behaviour no model has seen. The base rate when the value is unknown.
     */
    public double valueRate(double value) {
        if (Double.isNaN(value)) {
            return baseRate();
        }
        // A lower value is never safer: a run that went from 23 straight to its violation was below 22 too, though
        // no reading shows it. The rate at v is the highest rate at v or at a violating run's low above it.
        return lows.monotoneRate(value);
    }

    /**
     * P(violation | the property reads {@code value}, nothing else known): the value table's counts with the value
     * table's rate at that value ({@link #valueRate}, passed in by a caller that has it) as prior, the estimate of a
     * state that is "anywhere".
     */
    public double valueOnly(double value, double valueRate) {
        return (lows.violating(value) + PRIOR_RUNS * valueRate) / (lows.weight(value) + PRIOR_RUNS);
    }

    /**
     * Whether the forecast rule warns on {@code f}: its property is below the lowest value the training runs that held
     * went to ({@link Lows#safeFloor}), or the run does what the models know and its probability reaches the
     * threshold. The first is the raw-value baseline, which every rule keeps: a run is warned at least where and when
     * the one-line rule warns it. Once the run did something no learned machine does ({@link Forecast#novel}), no
     * model fits it and the rule falls back to that baseline alone: the threshold was chosen on forecasts of runs the
     * models knew, and a forecast resting on a re-synchronised suffix or on the value alone is no such forecast. Under
     * {@link Clauses#baseline} the baseline alone throughout. {@code beyondNominal} (no nominal machine matches the
     * run any more) adds nothing to the floor: such a run is warned by the same floor.
     */
    public boolean warns(Forecast f, boolean beyondNominal) {
        boolean below = f.value() != null && belowSafeFloor(f.value());
        return below || (!clauses.baseline() && !f.novel() && f.probability() >= threshold);
    }

    /** Whether the thesis's matching warns too, under the forecast rule ({@link Clauses#matching}). */
    public boolean matchingWarns() {
        return clauses.matching() && !clauses.baseline();
    }

    /** Whether {@code value} is below the lowest value of the training runs that held (false without such a run). */
    public boolean belowSafeFloor(double value) {
        return lows.safeCount() > 0 && value < lows.safeFloor();
    }

    /** This model with another warning threshold. */
    public ForecastModel withThreshold(double p, String note, boolean validated) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, p, note, validated, states,
                startInputs, calibration, scorecards, obligations, deadlines, bounds, clauses, events,
                deadlineCards, first, order);
    }

    /** This model with another calibration (the threshold is left as it is). */
    public ForecastModel withCalibration(Calibration c) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated,
                states, startInputs, c, scorecards, obligations, deadlines, bounds, clauses, events,
                deadlineCards, first, order);
    }

    /** This model with {@code cards} as its scorecards. */
    public ForecastModel withScorecards(List<Scorecard> cards) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated,
                states, startInputs, calibration, cards, obligations, deadlines, bounds, clauses, events,
                deadlineCards, first, order);
    }

    /** This model with {@code cards} as its deadline forecasts' scorecards, by property id. */
    public ForecastModel withDeadlineScorecards(Map<String, List<Scorecard>> cards) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated,
                states, startInputs, calibration, scorecards, obligations, deadlines, bounds, clauses, events, cards,
                first, order);
    }

    /** This model with its properties named: {@code id} the first floor's (null for none), {@code ids} in order. */
    ForecastModel named(String id, List<String> ids) {
        return new ForecastModel(format, unit, limit, runs, violating, lows, threshold, thresholdNote, validated,
                states, startInputs, calibration, scorecards, obligations, deadlines, bounds, clauses, events,
                deadlineCards, id, ids);
    }

    /**
     * What the forecast learned for each property, by kind, in the abstraction's order ({@link #order}; the first
     * floor first, then by id, when not known): the first floor as an ordinary bound with its floor as side.
     */
    public List<PropertyModel> properties() {
        return PropertyModels.of(this);
    }

    /** What the forecast learned for property {@code id}, by its kind; empty when it learned nothing for it. */
    public Optional<PropertyModel> property(String id) {
        return properties().stream().filter(p -> p.id().equals(id)).findFirst();
    }

    /**
     * The model of {@code properties} (in the abstraction's order) over {@code runs} training runs in {@code unit}:
     * the first bound forecast on its floor is the first floor ({@link PropertyModels#assemble}).
     */
    public static ForecastModel of(String unit, int runs, List<PropertyModel> properties) {
        return PropertyModels.assemble(unit, runs, properties);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ForecastModel m && format == m.format && unit.equals(m.unit)
                && Double.compare(limit, m.limit) == 0 && runs == m.runs && violating == m.violating
                && lows.equals(m.lows)
                && Double.compare(threshold, m.threshold) == 0 && thresholdNote.equals(m.thresholdNote) && validated == m.validated
                && states.equals(m.states) && startInputs.equals(m.startInputs) && calibration.equals(m.calibration)
                && scorecards.equals(m.scorecards) && obligations.equals(m.obligations) && deadlines.equals(m.deadlines)
                && bounds.equals(m.bounds) && clauses.equals(m.clauses) && events.equals(m.events)
                && deadlineCards.equals(m.deadlineCards) && Objects.equals(first, m.first) && order.equals(m.order);
    }

    @Override
    public int hashCode() {
        return 31 * runs + violating;
    }
}
