package dev.predmon.monitor;

import dev.predmon.forecast.Forecast;
import dev.predmon.property.PropertyChecker.PropertyVerdict;

import java.util.List;
import java.util.Optional;

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
 */
public record RunOutcome(int run, long firstLine, MonitorEvent.Warning warning, MonitorEvent.Violation violation,
                         boolean noMatch, long pairs, boolean safetyObserved, Forecast forecast,
                         List<PropertyVerdict> properties) {

    public RunOutcome {
        properties = List.copyOf(properties);
    }

    /** An outcome without a forecast. */
    public RunOutcome(int run, long firstLine, MonitorEvent.Warning warning, MonitorEvent.Violation violation,
                      boolean noMatch, long pairs, boolean safetyObserved) {
        this(run, firstLine, warning, violation, noMatch, pairs, safetyObserved, null, List.of());
    }

    /**
     * Whether the property was violated with no warning before it in the log: the run was missed (a warning at the
     * violating record or after it predicts nothing). The log's order, not its times, which may run backwards.
     */
    public boolean unwarnedViolation() {
        return violation != null && (warning == null || warning.line() >= violation.line());
    }

    /** Violation time minus warning time when both happened, in the log's unit. */
    public Optional<Double> lead() {
        return warning != null && violation != null ? Optional.of(violation.time() - warning.time()) : Optional.empty();
    }
}
