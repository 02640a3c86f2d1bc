package dev.predmon.evaluate;

import java.util.ArrayList;
import java.util.List;

/**
 * How good the forecast was on the judged runs, which none of the models saw in training.
 *
 * <p>Every run weighs the same: a run's forecasts (one per pair before its violation or end) share one unit of
 * weight, so a long run does not outvote a short one. The outcome of every forecast of a run is whether that run
 * violated the property. The Brier score, the calibration error and the reliability table are {@link Reliability}'s,
 * as for every other property's forecast.
 *
 * @param runs        runs with at least one forecast
 * @param brier       the mean squared distance between probability and outcome (0 is perfect)
 * @param baseBrier   the same for a forecaster that always says the training runs' share of violations
 * @param ece         expected calibration error: the weighted mean gap between predicted and observed in the bins
 * @param reliability predicted probability against observed frequency, in ten bins of the probability
 * @param sweep       recall and false alarms as the threshold moves (a run is warned when its highest forecast
 *                    before the violation reaches the threshold)
 * @param judged      the warning rule the runs were judged by, scored on the runs with a forecast
 * @param rawValue    the raw-value baseline on the same runs ({@link ValueRule#rawValue})
 * @param eceChance   the calibration error a calibrated forecast stays under on the same runs by chance, 9 times in 10
 */
public record ForecastScore(int runs, double brier, double baseBrier, double ece, List<Reliability.Bin> reliability,
                            List<Point> sweep, ValueRule judged, ValueRule rawValue, double eceChance) {

    /**
     * The forecast rule at one threshold.
     *
     * @param threshold   the probability at which it warns
     * @param warned      violating runs warned before their violation
     * @param violating   violating runs
     * @param falseAlarms runs that held but were warned
     * @param held        runs that held
     */
    public record Point(double threshold, int warned, int violating, int falseAlarms, int held) {
    }

    /** The score of {@code runs} (runs without forecasts are left out); null when none has one. */
    public static ForecastScore of(List<RunResult> runs) {
        List<RunResult> scored = runs.stream().filter(r -> r.forecast() != null
                && !r.forecast().probabilities().isEmpty()).toList();
        if (scored.isEmpty()) {
            return null;
        }
        Reliability r = Reliability.of(scored.stream().map(x -> Reliability.Run.of(x.forecast().probabilities(),
                x.violationTime() != null, x.forecast().baseRate())).toList());
        List<Point> sweep = new ArrayList<>();
        for (int i = 1; i <= 9; i++) {
            sweep.add(point(scored, i / 10.0));
        }
        return new ForecastScore(r.runs(), r.brier(), r.baseBrier(), r.ece(), r.bins(), List.copyOf(sweep),
                ValueRule.judged(runs), ValueRule.rawValue(runs), r.eceChance());
    }

    /** The forecast rule at threshold {@code t} over {@code runs}. */
    static Point point(List<RunResult> runs, double t) {
        int warned = 0;
        int violating = 0;
        int alarms = 0;
        int held = 0;
        for (RunResult r : runs) {
            boolean reached = r.forecast().peak() >= t;
            if (r.violationTime() != null) {
                violating++;
                warned += reached ? 1 : 0;
            } else {
                held++;
                alarms += reached ? 1 : 0;
            }
        }
        return new Point(t, warned, violating, alarms, held);
    }
}
