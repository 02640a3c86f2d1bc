package dev.predmon.forecast;

import java.util.ArrayList;
import java.util.List;

/**
 * Adds up held-out cases (runs, or a deadline's obligations) into a {@link Scorecard}, each judged as {@code watch}
 * would with a calibration and a threshold chosen without it: warned at its first calibrated forecast at the
 * threshold unless the rule's other clauses warned it first, scored by its Brier score against the base rate.
 */
public final class ScorecardTally {

    private int violating;
    private int warned;
    private int alarms;
    private int scored;
    private double brier;
    private double base;
    private final List<Double> leads = new ArrayList<>();

    /**
     * One held-out case.
     *
     * @param probabilities its raw forecasts, in order
     * @param times         when each was made
     * @param caughtAt      when the rule's other clauses warned it, NaN when they did not
     * @param violated      whether it violated (missed its deadline)
     * @param violationTime when it did (ignored when it did not)
     * @param baseRate      the base rate of the models that forecast it
     */
    public void add(List<Double> probabilities, List<Double> times, double caughtAt, boolean violated,
                    double violationTime, double baseRate, Calibration calibration, double threshold) {
        double y = violated ? 1 : 0;
        double warnedAt = caughtAt;
        double sum = 0;
        for (int i = 0; i < probabilities.size(); i++) {
            double p = calibration.apply(probabilities.get(i));
            sum += (p - y) * (p - y);
            if (p >= threshold && !(times.get(i) >= warnedAt)) {
                warnedAt = times.get(i); // the first forecast at the threshold, unless a clause came first
            }
        }
        if (!probabilities.isEmpty()) {
            brier += sum / probabilities.size();
            base += (baseRate - y) * (baseRate - y);
            scored++;
        }
        boolean warning = !Double.isNaN(warnedAt);
        if (violated) {
            violating++;
            if (warning) {
                warned++;
                leads.add(violationTime - warnedAt);
            }
        } else if (warning) {
            alarms++;
        }
    }

    /** The scorecard of {@code property} over the {@code cases} added, from {@code folds} folds. */
    public Scorecard scorecard(String property, int folds, int cases, String unit, String counted) {
        return new Scorecard(property, folds, cases, violating, warned, alarms, Scorecard.median(leads), unit,
                scored == 0 ? Double.NaN : brier / scored, scored == 0 ? Double.NaN : base / scored, counted);
    }
}
