package dev.predmon.monitor;

import dev.predmon.forecast.Forecast;
import dev.predmon.parse.Clock;

import java.util.List;

/**
 * What the predictive monitor reports, in log order. Times are the log's own: seconds where it has time stamps, else
 * the tree's tick number; each event's {@code clock} says which.
 */
public sealed interface MonitorEvent permits MonitorEvent.Warning, MonitorEvent.Violation, MonitorEvent.Eliminated,
        MonitorEvent.NoMatch, MonitorEvent.Restarted, MonitorEvent.RunStarted, MonitorEvent.Unmapped,
        MonitorEvent.ForecastChanged {

    /**
     * The run is predicted to violate the property: by the forecast rule, its probability reached the learned
     * threshold; by the match rule, every nominal scenario is eliminated while a faulty one still matches.
     *
     * @param time      time of the record that triggered it
     * @param line      its line in the log
     * @param scenarios the faulty scenarios still matching
     * @param battery   the last value seen on the safety property's channel (the battery level), or null
     * @param pairs     compacted query/reply pairs seen so far
     * @param clock     what {@code time} counts
     * @param run       the run of the log (0, 1, ... in a log that holds several)
     * @param rule      the rule that warned
     * @param forecast  the forecast at the warning, or null without one (models learned without forecasts)
     * @param reason    why, in an operator's words
     */
    record Warning(double time, long line, List<String> scenarios, Double battery, long pairs, Clock clock, int run,
                   WarningRule rule, Forecast forecast, String reason) implements MonitorEvent {

        /** A warning of the match rule without a forecast. */
        public Warning(double time, long line, List<String> scenarios, Double battery, long pairs, Clock clock,
                       int run) {
            this(time, line, scenarios, battery, pairs, clock, run, WarningRule.MATCH, null, onlyFaulty(scenarios));
        }

        /** The match rule's reason, in an operator's words: the run can only be one of the faulty {@code scenarios}. */
        static String onlyFaulty(List<String> scenarios) {
            return "the run can only be faulty scenario " + String.join(", ", scenarios)
                    + " (every nominal model eliminated)";
        }
    }

    /**
     * The forecast changed enough to be told (see {@code ForecastTracker}).
     *
     * @param time     time of the record that completed the pair
     * @param line     its line
     * @param forecast the new forecast
     * @param clock    what {@code time} counts
     * @param run      the run of the log
     */
    record ForecastChanged(double time, long line, Forecast forecast, Clock clock, int run) implements MonitorEvent {
    }

    /**
     * The built-in safety monitor saw the property violated (first time only).
     *
     * @param time     time of the violating record
     * @param line     its line
     * @param property the property's name
     * @param value    the violating value (the battery level)
     * @param before   the value of the reading before it on the same channel, or null when it was the first
     * @param clock    what {@code time} counts
     * @param run      the run of the log
     */
    record Violation(double time, long line, String property, double value, Double before, Clock clock, int run)
            implements MonitorEvent {
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
     * @param clock    what {@code time} counts
     * @param run      the run of the log
     */
    record Eliminated(double time, long line, String model, String scenario, boolean faulty, String reason,
                      Clock clock, int run) implements MonitorEvent {
    }

    /** No model matches any more: the run is unlike every learned scenario. */
    record NoMatch(double time, long line, Clock clock, int run) implements MonitorEvent {
    }

    /**
     * A new run of the robot begins in the log (its tick counter started again, or after a silence): every model
     * starts over from its initial state, and the run gets its own warning, violation and lead.
     *
     * @param run  its number (1, 2, ...; run 0 begins with the log)
     * @param time time of its first record
     * @param line line of its first record
     */
    record RunStarted(int run, double time, long line, Clock clock) implements MonitorEvent {
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
