package dev.predmon.evaluate;

import dev.predmon.forecast.Forecast;

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
 * @param batteryAtWarning the battery level at the warning, or null
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
 * @param sudden           whether the violation came in one reading from more than {@link #SUDDEN_MARGIN} points above
 *                         the threshold (the battery set by hand from 65% to 10%, say): the violation is the jump itself,
 *                         and no monitor that reads the battery can see it coming. False without a violation.
 * @param forecast         the run's forecasts, or null when the models carry none
 */
public record RunResult(String scenario, boolean faulty, String log, int fold, Verdict verdict, Double warningTime,
                        Long warningLine, List<String> warningScenarios, Double batteryAtWarning, Double violationTime,
                        Double lead, boolean noMatch, Double noMatchTime, long records, long pairs, int problems,
                        List<Elimination> eliminations, boolean safetyObserved, String unit, boolean sudden,
                        ForecastTrace forecast) {

    /** A result without forecasts. */
    public RunResult(String scenario, boolean faulty, String log, int fold, Verdict verdict, Double warningTime,
                     Long warningLine, List<String> warningScenarios, Double batteryAtWarning, Double violationTime,
                     Double lead, boolean noMatch, Double noMatchTime, long records, long pairs, int problems,
                     List<Elimination> eliminations, boolean safetyObserved, String unit, boolean sudden) {
        this(scenario, faulty, log, fold, verdict, warningTime, warningLine, warningScenarios, batteryAtWarning,
                violationTime, lead, noMatch, noMatchTime, records, pairs, problems, eliminations, safetyObserved, unit,
                sudden, null);
    }

    /**
     * What the forecast said during a run.
     *
     * @param probabilities the probability after each pair before the violation (or the end)
     * @param last          the last forecast of the run (for its last state), or null without a pair
     * @param atWarning     the forecast at the warning, or null
     * @param baseRate      the share of violating runs among the training runs of the models that judged it
     * @param threshold     the probability at which the forecast rule warns
     */
    public record ForecastTrace(List<Double> probabilities, Forecast last, Forecast atWarning, double baseRate,
                                double threshold) {

        /** The highest probability before the violation, 0 without a pair. */
        public double peak() {
            return probabilities.stream().mapToDouble(Double::doubleValue).max().orElse(0.0);
        }
    }

    /**
     * How far above the safety threshold the reading before a violation may be for the violation to count as
     * approached rather than sudden, in the property's unit (percentage points): one battery band of Section 5.2.
     */
    public static final double SUDDEN_MARGIN = 5.0;

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
