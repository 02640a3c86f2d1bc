package dev.predmon.evaluate;

import com.fasterxml.jackson.annotation.JsonProperty;
import dev.predmon.forecast.Forecast;
import dev.predmon.pipeline.RunId;

import java.util.List;

/**
 * How the monitor judged one test log, replayed through {@code watch}'s code path.
 *
 * @param scenario         the log's scenario (its directory)
 * @param faulty           whether that scenario is faulty
 * @param log              the log file; {@code file#k} for run k of a log that holds several
 * @param fold             the fold the log was tested in (0-based), or -1 with a separate test set
 * @param verdict          what the warning meant
 * @param warningTime      time of the warning, or null
 * @param warningLine      its line, or null
 * @param warningScenarios the faulty scenarios still matching at the warning (empty without one)
 * @param valueAtWarning   the watched value (the forecast's property's) at the warning, or null
 * @param violationTime    time of the safety monitor's first violation, or null
 * @param lead             violation time minus warning time for a hit, else null
 * @param noMatch          whether a point came where no model matched (unknown behaviour)
 * @param noMatchTime      when, or null
 * @param records          records parsed (-1 for one run of a log that holds several)
 * @param pairs            compacted pairs matched
 * @param problems         parse problems in the log
 * @param eliminations     every model's elimination, in log order
 * @param safetyObserved   whether the log had a value for the safety property at all (without one, "held" would
 *                         be a verdict on no evidence)
 * @param unit             what the times and the lead count: {@code s}, or {@code ticks} in a log without time stamps
 * @param sudden           whether the violation was sudden: fewer than {@link #SUDDEN_READINGS} readings lay within
 *                         {@link #APPROACH_BAND} points above the bound before it ({@code nearBound}), so the value
 *                         went from comfortable to violated in a few readings (the battery set by hand from 65% to
 *                         10%, say). A sudden violation can still be foreseen from the behaviour, and a run warned
 *                         ahead of one counts as warned ahead. False without a violation.
 * @param start            time of the run's first record, in {@code unit}: the report counts times from it
 * @param nearBound        readings of the safety property's value within {@link #APPROACH_BAND} points above its
 *                         bound (20 to 30 for a bound of 20) since it was last above that band, up to the violation
 *                         or, without one, to the end of the run
 * @param beforeViolation  the value read just before the violation on the same channel, or null (no violation, or
 *                         the violation was the first reading): how far the value fell in the violating reading
 * @param forecast         the run's forecasts, or null when the models carry none
 * @param properties       the abstraction's other properties (every one but the forecast's), each with its first
 *                         warning and violation in the run, in file order
 */
public record RunResult(String scenario, boolean faulty, RunId log, int fold, Verdict verdict, Double warningTime,
                        Long warningLine, List<String> warningScenarios, Double valueAtWarning, Double violationTime,
                        Double lead, boolean noMatch, Double noMatchTime, long records, long pairs, int problems,
                        List<Elimination> eliminations, boolean safetyObserved, String unit, boolean sudden,
                        double start, int nearBound, Double beforeViolation, ForecastTrace forecast,
                        List<PropertyResult> properties) {

    /** A result without the other properties. */
    public RunResult(String scenario, boolean faulty, RunId log, int fold, Verdict verdict, Double warningTime,
                     Long warningLine, List<String> warningScenarios, Double valueAtWarning, Double violationTime,
                     Double lead, boolean noMatch, Double noMatchTime, long records, long pairs, int problems,
                     List<Elimination> eliminations, boolean safetyObserved, String unit, boolean sudden,
                     double start, int nearBound, Double beforeViolation, ForecastTrace forecast) {
        this(scenario, faulty, log, fold, verdict, warningTime, warningLine, warningScenarios, valueAtWarning,
                violationTime, lead, noMatch, noMatchTime, records, pairs, problems, eliminations, safetyObserved, unit,
                sudden, start, nearBound, beforeViolation, forecast, List.of());
    }

    /**
     * One of the abstraction's other properties in the run.
     *
     * @param property  its id
     * @param warning   the time of its first warning (a deadline forecast, or the match rule's for a faulty scenario
     *                  that violates it), or null
     * @param violation the time of its violation, or null
     * @param beyond    when its baseline warned, or null: a deadline's elapsed-time rule (an obligation first pending
     *                  longer than every training obligation), a bound's raw-value rule (as the safety property's,
     *                  {@link Approach#belowFloor}), an absence's or a precedence's base rate (the run's start
     *                  where the training runs violated it at even odds or more)
     * @param forecasts what its forecast said before its violation (or the run's end), each forecast with its
     *                  outcome, and the base rate of the models that judged the run; null when it has no forecast
     * @param scope     what each forecast and its outcome are about: {@link #OBLIGATION} (a deadline forecast:
     *                  P(the pending obligation misses its deadline), outcome: that obligation missed it) or
     *                  {@link #RUN} (P(the run violates the property), outcome: it did); null without a forecast
     * @param verdict   its verdict at the run's end ({@code holds}, {@code pending}, {@code violated} or
     *                  {@code no-evidence}), or null where not known
     * @param words     that verdict in words ({@code no evidence (no GoTo/getStatus reply in the run)}), or null
     * @param noForecast why the models that judged the run gave it no forecast, in words ({@code never violated in
     *                   43 training runs}), or null
     */
    public record PropertyResult(String property, Double warning, Double violation, Double beyond,
                                 Reliability.Run forecasts, String scope, String verdict, String words,
                                 String noForecast) {

        /** A property not told why it has no forecast. */
        public PropertyResult(String property, Double warning, Double violation, Double beyond,
                              Reliability.Run forecasts, String scope, String verdict, String words) {
            this(property, warning, violation, beyond, forecasts, scope, verdict, words, null);
        }

        /** A property whose verdict at the run's end is not known. */
        public PropertyResult(String property, Double warning, Double violation, Double beyond,
                              Reliability.Run forecasts, String scope) {
            this(property, warning, violation, beyond, forecasts, scope, null, null);
        }

        /**
         * Whether nothing the property speaks of occurred in the run: neither a safe run nor a violating one for it
         * (a misspelt name, a scope that never opened).
         */
        public boolean noEvidence() {
            return "no-evidence".equals(verdict);
        }

        /** A deadline forecast's scope: one obligation. */
        public static final String OBLIGATION = "obligation";
        /** A forecast of the run's violation. */
        public static final String RUN = "run";

        /** A property without a forecast. */
        public PropertyResult(String property, Double warning, Double violation, Double beyond) {
            this(property, warning, violation, beyond, null, null);
        }

        /** A property no obligation of which went beyond the training ones. */
        public PropertyResult(String property, Double warning, Double violation) {
            this(property, warning, violation, null);
        }
    }

    /** A result without forecasts. */
    public RunResult(String scenario, boolean faulty, RunId log, int fold, Verdict verdict, Double warningTime,
                     Long warningLine, List<String> warningScenarios, Double valueAtWarning, Double violationTime,
                     Double lead, boolean noMatch, Double noMatchTime, long records, long pairs, int problems,
                     List<Elimination> eliminations, boolean safetyObserved, String unit, boolean sudden,
                     double start, int nearBound, Double beforeViolation) {
        this(scenario, faulty, log, fold, verdict, warningTime, warningLine, warningScenarios, valueAtWarning,
                violationTime, lead, noMatch, noMatchTime, records, pairs, problems, eliminations, safetyObserved, unit,
                sudden, start, nearBound, beforeViolation, null);
    }

    /**
     * What the forecast said during a run.
     *
     * @param probabilities the probability after each pair before the violation (or the end)
     * @param last          the last forecast of the run (for its last state), or null without a pair
     * @param atWarning     the forecast at the warning, or null
     * @param baseRate      the share of violating runs among the training runs of the models that judged it
     * @param threshold     the probability at which the forecast rule warns
     * @param valueRule     when the raw-value baseline ({@link ValueRule#rawValue}) warned: a reading below the
     *                      lowest value a safe training run read that began a stretch below it lasting to the
     *                      violation, or in a run that held the first such reading; null when none, or when the
     *                      training runs had no safe run with a reading
     * @param times         the log time at which each of {@code probabilities} was made (the time of the record that
     *                      made it), same length; empty where not known
     */
    public record ForecastTrace(List<Double> probabilities, Forecast last, Forecast atWarning, double baseRate,
                                double threshold, Double valueRule, List<Double> times) {

        public ForecastTrace {
            probabilities = List.copyOf(probabilities);
            times = List.copyOf(times);
            if (!times.isEmpty() && times.size() != probabilities.size()) {
                throw new IllegalArgumentException(times.size() + " times for " + probabilities.size()
                        + " probabilities");
            }
        }

        /** A trace without the times of its forecasts. */
        public ForecastTrace(List<Double> probabilities, Forecast last, Forecast atWarning, double baseRate,
                             double threshold, Double valueRule) {
            this(probabilities, last, atWarning, baseRate, threshold, valueRule, List.of());
        }

        /** A trace without the baseline's time and without the times of its forecasts. */
        public ForecastTrace(List<Double> probabilities, Forecast last, Forecast atWarning, double baseRate,
                             double threshold) {
            this(probabilities, last, atWarning, baseRate, threshold, null, List.of());
        }

        /** The highest probability before the violation, 0 without a pair. */
        public double peak() {
            return probabilities.stream().mapToDouble(Double::doubleValue).max().orElse(0.0);
        }
    }

    /**
     * How far above the bound a reading is near it, in the property's unit (percentage points): a violation
     * approached through this band gives the readings a monitor of the value needs to see it coming.
     */
    public static final double APPROACH_BAND = 10.0;

    /**
     * Readings near the bound ({@link #APPROACH_BAND}) below which a violation counts as sudden: ten readings are
     * ten ticks of the robot's tree, or a few seconds of a battery polled at 2-3 Hz.
     */
    public static final int SUDDEN_READINGS = 10;

    /** {@link #valueAtWarning} under its older name in the evaluation's JSON, kept for existing scripts. */
    @JsonProperty("batteryAtWarning")
    public Double batteryAtWarning() {
        return valueAtWarning;
    }

    /** {@code time} (a log time, such as the warning's) counted from the start of the run, or null. */
    public Double sinceStart(Double time) {
        return time == null ? null : time - start;
    }

    /**
     * A model stopped matching.
     *
     * @param model    its id
     * @param scenario its scenario
     * @param faulty   whether that scenario is faulty
     * @param time     time of the record that eliminated it
     * @param line     that record's line
     * @param reason   expected versus seen
     */
    public record Elimination(String model, String scenario, boolean faulty, double time, long line, String reason) {
    }
}
