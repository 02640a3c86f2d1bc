package dev.predmon.evaluate;

import java.util.ArrayList;
import java.util.List;

/**
 * A warning rule beside the forecast, judged on the same held-out runs: what it adds is what a user learns the
 * machines for. The baseline is a rule on the raw value alone, chosen by the same cross-validation as the forecast:
 * warn at a reading below the lowest value any safe run of the fold's training runs read (the floor the forecast's
 * own novelty clause uses), until the value is back at or above it. It needs no machine and no threshold. A violation
 * counts as warned ahead when the stretch below the floor lasted up to it; a run that held and went below the floor
 * is a false alarm.
 *
 * @param rule        the rule, in words
 * @param warned      violating runs warned before their violation
 * @param violating   violating runs
 * @param falseAlarms runs that held but were warned
 * @param held        runs that held
 * @param lead        lead of the warned violating runs, in the runs' unit
 */
public record ValueRule(String rule, int warned, int violating, int falseAlarms, int held, Stats lead) {

    /** The raw-value baseline's words. */
    public static final String RAW_VALUE = "raw value: warn below the lowest value a safe training run read";
    /** The forecast's own rule, scored the same way. */
    public static final String FORECAST = "the forecast's warning rule";

    /** The raw-value baseline on {@code runs} (runs without a forecast, so without a learned floor, left out). */
    public static ValueRule rawValue(List<RunResult> runs) {
        return score(RAW_VALUE, runs, true);
    }

    /** The warning rule the runs were judged by, scored on the same runs as {@link #rawValue}. */
    public static ValueRule judged(List<RunResult> runs) {
        return score(FORECAST, runs, false);
    }

    private static ValueRule score(String name, List<RunResult> runs, boolean baseline) {
        int warned = 0;
        int violating = 0;
        int alarms = 0;
        int held = 0;
        List<Double> leads = new ArrayList<>();
        for (RunResult r : runs) {
            if (r.forecast() == null) {
                continue;
            }
            Double at = baseline ? r.forecast().valueRule() : r.warningTime();
            if (r.violationTime() != null) {
                violating++;
                if (at != null && at < r.violationTime()) {
                    warned++;
                    leads.add(r.violationTime() - at);
                }
            } else {
                held++;
                alarms += at != null ? 1 : 0;
            }
        }
        return new ValueRule(name, warned, violating, alarms, held, Stats.of(leads));
    }
}
