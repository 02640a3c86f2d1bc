package dev.predmon.monitor;

import dev.predmon.parse.LogRecord;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

/**
 * What the current run has shown the {@link PredictiveMonitor} so far: its number and first line, its first warnings
 * and violation, its last record, the pairs matched and where the thesis's rule first held. All of it but the log's
 * first warning and violation starts over with every run ({@link #start}); what else outlives a run is the monitor's
 * {@link RunHistory}.
 */
final class RunState {

    /** The run: 0, then 1, 2, ... in a log that holds several. */
    int run;
    /** The line of the run's first record. */
    long firstLine = 1;
    /** The forecast property's first warning (the forecast's or the thesis's rule), or null. */
    MonitorEvent.Warning warning;
    /** The first warning of any property: {@link #warning}, or a deadline's; null before one. */
    MonitorEvent.Warning anyWarning;
    /** Each property's first warning in the run, by id, in the order they came. */
    final Map<String, MonitorEvent.Warning> warnings = new LinkedHashMap<>();
    /** The forecast property's first violation, or null. */
    MonitorEvent.Violation violation;
    /** Whether a point came where no model, nominal or faulty, matched the run any more. */
    boolean noMatch;
    /** The run's last record, null before one. */
    LogRecord last;
    /** Compacted pairs matched. */
    long pairs;
    /** The pair at which the thesis's match rule first held (confirm included), or -1. */
    long matchRuleAt = -1;
    /**
     * The records the monitor has read since it started, the one it takes now included: the order of reading, which
     * outlives runs and rotations (a run may hold records of two files, each with lines of its own).
     */
    long read;
    /** Where in that order the run's first warning of any property, and its first violation, came; 0 before. */
    long warningRead;
    long violationRead;

    /** Run {@code number} begins at {@code line}: nothing seen yet. */
    void start(int number, long line) {
        run = number;
        firstLine = line;
        warning = null;
        anyWarning = null;
        warnings.clear();
        violation = null;
        noMatch = false;
        last = null;
        pairs = 0;
        matchRuleAt = -1;
        warningRead = 0;
        violationRead = 0;
    }

    /** The log's first warning and violation of the headline property (of any run): they outlive the run. */
    MonitorEvent.Warning firstWarning;
    MonitorEvent.Violation firstViolation;

    /**
     * A warning of some property: kept when it is the run's first (with where it came in the order of reading), and
     * when it is its property's first.
     */
    void anyWarned(MonitorEvent.Warning w) {
        if (anyWarning == null) {
            anyWarning = w;
            warningRead = read;
        }
        if (w.property() != null) {
            warnings.putIfAbsent(w.property(), w);
        }
    }

    /**
     * {@code e}, an event the monitor tells, {@code headline} the id of the property the outcome headlines: keeps the
     * run's first warning of any property and of each, the run's and the log's first warning and violation of the
     * headline property, and where in reading order the run's first violation came.
     */
    MonitorEvent told(MonitorEvent e, String headline) {
        if (e instanceof MonitorEvent.Violation && violationRead == 0) {
            violationRead = read;
        }
        if (e instanceof MonitorEvent.Warning w) {
            anyWarned(w);
            if (Objects.equals(w.property(), headline)) {
                warning = warning == null ? w : warning;
                firstWarning = firstWarning == null ? w : firstWarning;
            }
        } else if (e instanceof MonitorEvent.Violation v && v.forecast()) {
            violation = violation == null ? v : violation;
            firstViolation = firstViolation == null ? v : firstViolation;
        }
        return e;
    }
}
