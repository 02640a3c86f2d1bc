package dev.predmon.monitor;

import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.Survival;
import dev.predmon.parse.Clock;

import java.util.List;
import java.util.Locale;

/**
 * What the predictive monitor reports, in log order. Times are the log's own: seconds where it has time stamps, else
 * the tree's tick number; each event's {@code clock} says which.
 */
public sealed interface MonitorEvent permits MonitorEvent.Warning, MonitorEvent.Violation, MonitorEvent.Eliminated,
        MonitorEvent.NoMatch, MonitorEvent.Restarted, MonitorEvent.RunStarted, MonitorEvent.Unmapped,
        MonitorEvent.ForecastChanged, MonitorEvent.Recovered, MonitorEvent.UnderWay {

    /** Which clause of the warning rule warned. */
    enum Clause {
        /** The forecast's probability reached the warning threshold. */
        FORECAST,
        /** The thesis's matching: the run can only be one of the faulty scenarios. */
        MATCHING,
        /** The run does something no safe training run did, with its value below every safe run's lowest. */
        NOVELTY,
        /**
         * A bounded response's deadline forecast: a miss at even odds, or an obligation pending past every training
         * one ({@code DeadlineFollow}).
         */
        DEADLINE;

        /** As in JSON: {@code forecast}, {@code matching}, {@code novelty}. */
        public String id() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /**
     * The run is predicted to violate the property: by the forecast rule, its probability reached the learned
     * threshold; by the match rule, every nominal scenario is eliminated while a faulty one still matches.
     *
     * @param time      time of the record that triggered it
     * @param line      its line in the log
     * @param scenarios the faulty scenarios still matching
     * @param value     the warned property's value at the warning: the last reading on the forecast's property's
     *                  channel (e.g. the battery level), or null before any and for a deadline's warning (a bounded
     *                  response has no value)
     * @param pairs     compacted query/reply pairs seen so far
     * @param clock     what {@code time} counts
     * @param run       the run of the log (0, 1, ... in a log that holds several)
     * @param rule      the rule that warned
     * @param forecast  the forecast at the warning, or null without one (models learned without forecasts)
     * @param reason    why, in an operator's words
     * @param clause    which clause of the rule warned
     * @param scenario  the faulty scenario the run is most like: the first still matching, else the one whose
     *                  machine matched the run longest, or null when no faulty machine ever matched it
     * @param property  the id of the property whose violation is predicted (the forecast's, or a bounded response's
     *                  for a deadline), or null when the abstraction has none
     * @param deadline  for {@link Clause#DEADLINE}, the deadline forecast that warned ({@code forecast} is then null);
     *                  else null
     */
    record Warning(double time, long line, List<String> scenarios, Double value, long pairs, Clock clock, int run,
                   WarningRule rule, Forecast forecast, String reason, Clause clause, String scenario,
                   String property, Survival.Estimate deadline) implements MonitorEvent {

        /** A warning of the forecast's property, or of the match rule. */
        public Warning(double time, long line, List<String> scenarios, Double value, long pairs, Clock clock,
                       int run, WarningRule rule, Forecast forecast, String reason, Clause clause, String scenario,
                       String property) {
            this(time, line, scenarios, value, pairs, clock, run, rule, forecast, reason, clause, scenario,
                    property, null);
        }

        /** A warning whose scenario is the first still matching, for a property not named. */
        public Warning(double time, long line, List<String> scenarios, Double value, long pairs, Clock clock,
                       int run, WarningRule rule, Forecast forecast, String reason, Clause clause) {
            this(time, line, scenarios, value, pairs, clock, run, rule, forecast, reason, clause,
                    scenarios.isEmpty() ? null : scenarios.get(0), null);
        }

        /** A warning whose clause its rule and reason tell (the match rule's, or the forecast rule's own words). */
        public Warning(double time, long line, List<String> scenarios, Double value, long pairs, Clock clock,
                       int run, WarningRule rule, Forecast forecast, String reason) {
            this(time, line, scenarios, value, pairs, clock, run, rule, forecast, reason,
                    rule == WarningRule.MATCH || reason.startsWith(ONLY_FAULTY) ? Clause.MATCHING
                            : reason.contains(ForecastTracker.REACHES) ? Clause.FORECAST : Clause.NOVELTY);
        }

        /** A warning of the match rule without a forecast. */
        public Warning(double time, long line, List<String> scenarios, Double value, long pairs, Clock clock,
                       int run) {
            this(time, line, scenarios, value, pairs, clock, run, WarningRule.MATCH, null, onlyFaulty(scenarios));
        }

        /** The match rule's reason, in an operator's words: the run can only be one of the faulty {@code scenarios}. */
        static String onlyFaulty(List<String> scenarios) {
            return ONLY_FAULTY + String.join(", ", scenarios)
                    + " (every nominal model eliminated)";
        }
    }

    /** How the match rule's reason begins. */
    String ONLY_FAULTY = "the run can only be faulty scenario ";

    /**
     * A warning, or a violation, ended because its cause ended: the property holds again, the forecast no longer
     * warns and the value rose above where it warned, or the action recovered the run. The alarm is gone; the
     * forecast starts over, and a later warning or violation of the run is reported again.
     *
     * @param time   time of the reading that ended it
     * @param line   its line
     * @param cause    {@code property} (the property holds again after its violation), {@code forecast} or
     *                 {@code action}; for a bounded response's deadline warning, {@code discharged} (the response came
     *                 in time); for a bound with a scope, {@code scope} (the scope closed); {@value #RUN_ENDED} for
     *                 an alarm still up when its run ended (nothing recovered: the run is over)
     * @param value    the property's value there (NaN for a property without one, a bounded response)
     * @param reason   why, in an operator's words
     * @param clock    what {@code time} counts
     * @param run      the run of the log
     * @param property the id of the property whose alarm ended, or null when not known
     */
    record Recovered(double time, long line, String cause, double value, String reason, Clock clock, int run,
                     String property) implements MonitorEvent {

        /** The cause of an alarm that ended with its run: a new run began, or the log was restarted. */
        public static final String RUN_ENDED = "run-ended";

        /** A recovery of no named property. */
        public Recovered(double time, long line, String cause, double value, String reason, Clock clock, int run) {
            this(time, line, cause, value, reason, clock, run, null);
        }
    }

    /**
     * The safety property's recommended action started to be under way (the abstraction's {@code underWay}
     * messages: the robot already does what an operator would tell it to), or stopped being so.
     *
     * @param time     time of the record
     * @param line     its line
     * @param by       the message, in a few words ({@code goTo charging_station})
     * @param underWay true when it started, false when it stopped
     * @param clock    what {@code time} counts
     * @param run      the run of the log
     */
    record UnderWay(double time, long line, String by, boolean underWay, Clock clock, int run)
            implements MonitorEvent {
    }

    /**
     * The forecast changed enough to be told (see {@code ForecastTracker}), or a bounded response's deadline forecast
     * changed as the page shows it ({@code DeadlineFollow}: its probability of a miss in whole percent, or whether it is
     * past every training obligation).
     *
     * @param time     time of the record that completed the pair
     * @param line     its line
     * @param forecast the new forecast, or null for a deadline's
     * @param clock    what {@code time} counts
     * @param run      the run of the log
     * @param property the id of the property forecast, or null when not known
     * @param deadline a bounded response's deadline forecast ({@code forecast} is then null), else null
     * @param unit     what {@code deadline}'s time left counts ({@code ticks}, {@code seconds}, {@code occurrences}),
     *                 else null
     */
    record ForecastChanged(double time, long line, Forecast forecast, Clock clock, int run, String property,
                           Survival.Estimate deadline, String unit) implements MonitorEvent {

        /** A forecast, of a deadline without its unit. */
        public ForecastChanged(double time, long line, Forecast forecast, Clock clock, int run, String property,
                               Survival.Estimate deadline) {
            this(time, line, forecast, clock, run, property, deadline, null);
        }

        /** A forecast of the forecast's property. */
        public ForecastChanged(double time, long line, Forecast forecast, Clock clock, int run, String property) {
            this(time, line, forecast, clock, run, property, null);
        }

        /** A forecast of no named property. */
        public ForecastChanged(double time, long line, Forecast forecast, Clock clock, int run) {
            this(time, line, forecast, clock, run, null);
        }
    }

    /**
     * The safety monitor saw a property violated (its first violation in the run).
     *
     * @param time     time of the violating record
     * @param line     its line
     * @param property the property's id ({@code battery}, {@code no-abort})
     * @param name     the property in words
     * @param value    the violating value of a bound property (the battery level), or null for an event
     * @param before   the value of the reading before it on the same channel, or null
     * @param what     what violated it, in words ({@code GoTo/getStatus reply 3}), or null
     * @param clock    what {@code time} counts
     * @param run      the run of the log
     * @param forecast whether it is the property the forecast and the warnings are about, whose violation the lead,
     *                 the hits and the exit codes count
     */
    record Violation(double time, long line, String property, String name, Double value, Double before, String what,
                     Clock clock, int run, boolean forecast) implements MonitorEvent {

        /** A violation of the forecast's bound property, named by {@code property} alone. */
        public Violation(double time, long line, String property, double value, Double before, Clock clock, int run) {
            this(time, line, property, property, value, before, null, clock, run, true);
        }
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
     * @param message its kind
     */
    record Unmapped(double time, long line, UnmappedMessage message) implements MonitorEvent {
    }

    /**
     * The log was truncated or replaced, or the connection to a live robot was lost and made again: the run ends, and
     * matching starts over in a new one.
     *
     * @param reason {@value #TRUNCATED}, {@value #REPLACED} or {@value #RECONNECTED}
     */
    record Restarted(String reason) implements MonitorEvent {

        public static final String TRUNCATED = "truncated";
        public static final String REPLACED = "replaced";
        public static final String RECONNECTED = "reconnected";

        /** What ended the run, in words: {@code the log was truncated}, {@code the connection ... was lost}. */
        public String words() {
            return words(reason);
        }

        /** As {@link #words()}, for {@code reason}. */
        public static String words(String reason) {
            return RECONNECTED.equals(reason) ? "the connection to the robot was lost and made again"
                    : "the log was " + reason;
        }
    }
}
