package dev.predmon.monitor;

import dev.predmon.forecast.Forecast;
import dev.predmon.property.PropertyChecker.PropertyVerdict;
import dev.predmon.property.Verdict;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.UnaryOperator;

/**
 * What the predictive monitor saw in one run of a log.
 *
 * @param run       0, 1, ... in log order
 * @param firstLine the line of its first record
 * @param warning   its warning, or null
 * @param violation its first violation, or null
 * @param noMatch   whether a point came where no model matched
 * @param pairs     compacted pairs matched
 * @param safetyObserved whether the run had a value for the safety property at all (without one, "held" would be a
 *                       verdict on no evidence)
 * @param forecast  the run's last forecast (for its last state), or null without one
 * @param properties every property of the abstraction with its verdict on the run, in file order
 * @param firstWarning the run's first warning of any property (the forecast's, or a bounded response's deadline),
 *                     or null
 * @param warnings  each property's first warning in the run, by its id, in the order they came: with the
 *                  violated verdicts in {@code properties}, the run's outcome ({@link PropertyOutcome#of})
 * @param warningRead  the place in the order of reading (1 for the first record the monitor took, across files) of
 *                     the record that gave {@code firstWarning}, 0 without one or when not known
 * @param violationRead the same for the run's first violation of any property
 */
public record RunOutcome(int run, long firstLine, MonitorEvent.Warning warning, MonitorEvent.Violation violation,
                         boolean noMatch, long pairs, boolean safetyObserved, Forecast forecast,
                         List<PropertyVerdict> properties, MonitorEvent.Warning firstWarning,
                         Map<String, MonitorEvent.Warning> warnings, long warningRead, long violationRead) {

    public RunOutcome {
        properties = List.copyOf(properties);
        warnings = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(warnings));
    }

    /** An outcome whose order of reading is not known: its lines tell it (one file). */
    public RunOutcome(int run, long firstLine, MonitorEvent.Warning warning, MonitorEvent.Violation violation,
                      boolean noMatch, long pairs, boolean safetyObserved, Forecast forecast,
                      List<PropertyVerdict> properties, MonitorEvent.Warning firstWarning,
                      Map<String, MonitorEvent.Warning> warnings) {
        this(run, firstLine, warning, violation, noMatch, pairs, safetyObserved, forecast, properties, firstWarning,
                warnings, 0, 0);
    }

    /** An outcome whose warnings by property are its first warning's and the forecast property's. */
    public RunOutcome(int run, long firstLine, MonitorEvent.Warning warning, MonitorEvent.Violation violation,
                      boolean noMatch, long pairs, boolean safetyObserved, Forecast forecast,
                      List<PropertyVerdict> properties, MonitorEvent.Warning firstWarning) {
        this(run, firstLine, warning, violation, noMatch, pairs, safetyObserved, forecast, properties, firstWarning,
                byProperty(firstWarning, warning));
    }

    private static Map<String, MonitorEvent.Warning> byProperty(MonitorEvent.Warning... ws) {
        Map<String, MonitorEvent.Warning> m = new LinkedHashMap<>();
        for (MonitorEvent.Warning w : ws) {
            if (w != null && w.property() != null) {
                m.putIfAbsent(w.property(), w);
            }
        }
        return m;
    }

    /** {@code warnings} with each warning's times as {@code convert} gives them (in seconds, once a tick's length is known). */
    static Map<String, MonitorEvent.Warning> inSeconds(Map<String, MonitorEvent.Warning> warnings,
                                                       UnaryOperator<MonitorEvent> convert) {
        Map<String, MonitorEvent.Warning> m = new LinkedHashMap<>();
        warnings.forEach((id, w) -> m.put(id, (MonitorEvent.Warning) convert.apply(w)));
        return m;
    }

    /** The ids of the properties violated in the run, in the abstraction's order. */
    public List<String> violatedProperties() {
        return properties.stream().filter(pv -> pv.verdict() instanceof Verdict.Violated)
                .map(pv -> pv.property().id()).toList();
    }

    /** The ids of the properties warned of in the run, in the order the warnings came. */
    public List<String> warnedProperties() {
        return List.copyOf(warnings.keySet());
    }

    /** An outcome whose only warnings are the forecast property's. */
    public RunOutcome(int run, long firstLine, MonitorEvent.Warning warning, MonitorEvent.Violation violation,
                      boolean noMatch, long pairs, boolean safetyObserved, Forecast forecast,
                      List<PropertyVerdict> properties) {
        this(run, firstLine, warning, violation, noMatch, pairs, safetyObserved, forecast, properties, warning);
    }

    /** An outcome without a forecast. */
    public RunOutcome(int run, long firstLine, MonitorEvent.Warning warning, MonitorEvent.Violation violation,
                      boolean noMatch, long pairs, boolean safetyObserved) {
        this(run, firstLine, warning, violation, noMatch, pairs, safetyObserved, null, List.of());
    }

    /** Whether a warning of some property was raised in the run. */
    public boolean warned() {
        return firstWarning != null;
    }

    /**
     * Whether some property was violated with no warning of any property before that violation: the run was missed
     * (a warning at the violating record or after it predicts nothing). "Before" is the order in which the records
     * were read, not their times, which may run backwards, nor their lines: after a rename rotation with two writers
     * a run holds records of two files, each numbered in its own. A warning before the run's first violation comes
     * before every later one, so that one decides.
     */
    public boolean unwarnedViolation() {
        long first = firstViolationLine();
        if (first == 0) {
            return false;
        }
        if (firstWarning == null) {
            return true;
        }
        return (warningRead > 0 && violationRead > 0) ? warningRead >= violationRead : firstWarning.line() >= first;
    }

    /** The line of the run's first violation of any property, 0 without one. */
    private long firstViolationLine() {
        long first = violation == null ? Long.MAX_VALUE : violation.line();
        for (PropertyVerdict pv : properties) {
            if (pv.verdict() instanceof Verdict.Violated v) {
                first = Math.min(first, v.line());
            }
        }
        return first == Long.MAX_VALUE ? 0 : first;
    }

    /** Violation time minus warning time when both happened, in the log's unit. */
    public Optional<Double> lead() {
        return warning != null && violation != null ? Optional.of(violation.time() - warning.time()) : Optional.empty();
    }
}
