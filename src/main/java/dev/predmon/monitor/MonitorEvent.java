package dev.predmon.monitor;

import java.util.List;

/** What the predictive monitor reports, in log order. Times are the log's time stamps. */
public sealed interface MonitorEvent permits MonitorEvent.Warning, MonitorEvent.Violation, MonitorEvent.Eliminated,
        MonitorEvent.NoMatch, MonitorEvent.Restarted, MonitorEvent.Unmapped {

    /**
     * Every nominal scenario is eliminated while a faulty one still matches: the run is predicted to fail.
     *
     * @param time      time of the record that triggered it
     * @param line      its line in the log
     * @param scenarios the faulty scenarios still matching
     * @param battery   the last value seen on the safety property's channel (the battery level), or null
     * @param pairs     compacted query/reply pairs seen so far
     */
    record Warning(double time, long line, List<String> scenarios, Double battery, long pairs) implements MonitorEvent {
    }

    /**
     * The built-in safety monitor saw the property violated (first time only).
     *
     * @param time     time of the violating record
     * @param line     its line
     * @param property the property's name
     * @param value    the violating value (the battery level)
     */
    record Violation(double time, long line, String property, double value) implements MonitorEvent {
    }

    /**
     * A model stopped matching the run.
     *
     * @param time     time of the record that triggered it
     * @param line     its line
     * @param model    the model's id
     * @param scenario its scenario
     * @param faulty   whether that scenario is faulty
     * @param reason   why (expected versus seen)
     */
    record Eliminated(double time, long line, String model, String scenario, boolean faulty, String reason)
            implements MonitorEvent {
    }

    /** No model matches any more: the run is unlike every learned scenario. */
    record NoMatch(double time, long line) implements MonitorEvent {
    }

    /**
     * The first interface message of its kind that no abstraction rule maps (since the start or a restart): it is
     * not matched, and is reported rather than silently dropped.
     *
     * @param time    its time
     * @param line    its line
     * @param message its kind, {@code Protocol/command}
     */
    record Unmapped(double time, long line, String message) implements MonitorEvent {
    }

    /** The log was truncated or replaced; matching starts over. */
    record Restarted(String reason) implements MonitorEvent {
    }
}
