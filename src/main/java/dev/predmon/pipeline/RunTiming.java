package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.Classification;
import dev.predmon.parse.LogRecord;

import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * When the pairs of one run came and what the safety property's channel read then: the forecast learns from it how
 * long runs took from a state to their violation or end, and how the property drifted.
 *
 * @param times         the log time of each pair's completing record, in the log's unit (seconds or ticks)
 * @param values        the property's last value at each pair (the battery level), NaN before the first reading
 * @param violationTime when the safety monitor first saw the property violated in this run, NaN when it held
 * @param endTime       the time of the run's last record, NaN when no record had a time
 * @param lowestSafeValue the property's lowest value before the violation (in the whole run when it held), NaN
 *                      without a reading: how low the run went while still safe
 * @param unit          what the times count: {@code s}, or {@code ticks} in a log without time stamps
 * @param readings      every change of the property's value in the run, in order, with the number of pairs completed
 *                      before it: the forecast moves with the value between pairs too
 * @param gaps          where the trace misses a step: the interface messages of the run that the abstraction cannot
 *                      name ({@link UnmappedMessages#novelty}), in order, so that the forecast made offline treats them
 *                      as {@code watch} does
 * @param obligations   how each obligation of the abstraction's bounded-response properties ended in the run, in
 *                      order: what the deadline forecast learns from
 * @param violations    the run's outcome: by property id, when the safety monitor first saw each property it violated
 *                      (in the log's unit; NaN for a record without a time), the properties it held absent
 * @param bounds        by id, every bound property but the safety property: each change of its value in the run, in
 *                      order, as {@code readings} holds the safety property's (what its own forecast learns from)
 * @param unobserved    the ids of the properties the run gave no evidence for (nothing they speak of occurred:
 *                      {@link dev.predmon.property.Verdict.NoEvidence}), neither safe nor violating for them
 */
// Arrays: one number per pair, read by index; a run's timing is never compared or hashed.
@SuppressWarnings("ArrayRecordComponent")
public record RunTiming(double[] times, double[] values, double violationTime, double endTime,
                        double lowestSafeValue, String unit, List<Reading> readings, List<Gap> gaps,
                        List<Obligation> obligations, Map<String, Double> violations,
                        Map<String, List<Reading>> bounds, Set<String> unobserved) {

    /** As above, with evidence for every property. */
    public RunTiming(double[] times, double[] values, double violationTime, double endTime, double lowestSafeValue,
                     String unit, List<Reading> readings, List<Gap> gaps, List<Obligation> obligations,
                     Map<String, Double> violations, Map<String, List<Reading>> bounds) {
        this(times, values, violationTime, endTime, lowestSafeValue, unit, readings, gaps, obligations, violations,
                bounds, Set.of());
    }

    /** As above, without the other bound properties' readings. */
    public RunTiming(double[] times, double[] values, double violationTime, double endTime, double lowestSafeValue,
                     String unit, List<Reading> readings, List<Gap> gaps, List<Obligation> obligations,
                     Map<String, Double> violations) {
        this(times, values, violationTime, endTime, lowestSafeValue, unit, readings, gaps, obligations, violations,
                Map.of());
    }

    /** As above, without the outcome per property. */
    public RunTiming(double[] times, double[] values, double violationTime, double endTime, double lowestSafeValue,
                     String unit, List<Reading> readings, List<Gap> gaps, List<Obligation> obligations) {
        this(times, values, violationTime, endTime, lowestSafeValue, unit, readings, gaps, obligations, Map.of());
    }

    /** As above, without obligations. */
    public RunTiming(double[] times, double[] values, double violationTime, double endTime, double lowestSafeValue,
                     String unit, List<Reading> readings, List<Gap> gaps) {
        this(times, values, violationTime, endTime, lowestSafeValue, unit, readings, gaps, List.of());
    }

    /** As above, with a trace that misses no step. */
    public RunTiming(double[] times, double[] values, double violationTime, double endTime, double lowestSafeValue,
                     String unit, List<Reading> readings) {
        this(times, values, violationTime, endTime, lowestSafeValue, unit, readings, List.of());
    }

    /**
     * One obligation of a bounded-response property, as it ended.
     *
     * @param property   the property's id
     * @param duration   how long it was pending, in the deadline's unit
     * @param discharged whether its response came (else it was let go still pending: a censored duration)
     * @param input      the Mealy input its trigger record maps to ({@link #inputOf}), or null when it maps to none
     */
    public record Obligation(String property, double duration, boolean discharged, String input) {

        /** An obligation whose trigger's input is not known. */
        public Obligation(String property, double duration, boolean discharged) {
            this(property, duration, discharged, null);
        }
    }

    /**
     * The Mealy input {@code abstraction} maps {@code trigger} to (the skill asked for, with where to), null when it is
     * no mapped message: the condition of a deadline forecast ({@code forecast.Survival#at}).
     */
    public static String inputOf(Abstraction abstraction, LogRecord trigger) {
        return abstraction.classify(trigger) instanceof Classification.Mapped m ? m.event().symbol() : null;
    }

    /**
     * A message the abstraction cannot name.
     *
     * @param line        its line in the log
     * @param pairsBefore pairs of the run completed before it
     */
    public record Gap(long line, int pairsBefore) {
    }

    /**
     * A new value of the property.
     *
     * @param time        its record's time
     * @param value       the value
     * @param pairsBefore pairs of the run completed before it
     */
    public record Reading(double time, double value, int pairsBefore) {
    }

    public RunTiming {
        if (times.length != values.length) {
            throw new IllegalArgumentException("times and values differ in length: " + times.length + " vs "
                    + values.length);
        }
        times = times.clone();
        values = values.clone();
        readings = List.copyOf(readings);
        gaps = List.copyOf(gaps);
        obligations = List.copyOf(obligations);
        violations = Map.copyOf(violations);
        Map<String, List<Reading>> copy = new TreeMap<>();
        bounds.forEach((id, r) -> copy.put(id, List.copyOf(r)));
        bounds = Collections.unmodifiableMap(copy);
        unobserved = Set.copyOf(unobserved);
    }

    /** Whether the run violated the property {@code id} (its outcome as the safety monitor saw it). */
    public boolean violated(String id) {
        return violations.containsKey(id);
    }

    /** Whether the run gave evidence for the property {@code id} (something it speaks of occurred). */
    public boolean observed(String id) {
        return !unobserved.contains(id);
    }

    /** No timing known for {@code pairs} pairs (every time and value NaN). */
    public static RunTiming none(int pairs) {
        double[] nan = new double[pairs];
        Arrays.fill(nan, Double.NaN);
        return new RunTiming(nan, nan, Double.NaN, Double.NaN, Double.NaN, "s", List.of());
    }

    /** The time of pair {@code i}. */
    public double time(int i) {
        return times[i];
    }

    /** The property's value at pair {@code i}. */
    public double value(int i) {
        return values[i];
    }

    public int size() {
        return times.length;
    }

    @Override
    public double[] times() {
        return times.clone();
    }

    @Override
    public double[] values() {
        return values.clone();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof RunTiming t && Arrays.equals(times, t.times) && Arrays.equals(values, t.values)
                && Double.compare(violationTime, t.violationTime) == 0 && Double.compare(endTime, t.endTime) == 0
                && Double.compare(lowestSafeValue, t.lowestSafeValue) == 0 && unit.equals(t.unit) && readings.equals(t.readings)
                && gaps.equals(t.gaps);
    }

    @Override
    public int hashCode() {
        return 31 * Arrays.hashCode(times) + Arrays.hashCode(values);
    }

    @Override
    public String toString() {
        return "RunTiming[" + times.length + " pairs, violation " + violationTime + ", end " + endTime + "]";
    }
}
