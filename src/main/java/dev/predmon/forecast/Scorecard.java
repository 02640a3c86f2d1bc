package dev.predmon.forecast;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * How good the forecast of one property was on runs the judging models did not see: the cross-validation that
 * chooses the warning threshold, with every held-out run forecast by the machines and statistics learned without it,
 * then judged by the forecast rule with a calibration and a threshold chosen from the other folds' runs. Stored with
 * the models ({@code forecast.json}), so that whoever watches with them can tell how far to trust them.
 *
 * @param property    the property's name, as the abstraction gives it
 * @param folds       folds of the cross-validation
 * @param runs        held-out runs judged
 * @param violating   of them, the runs that violated the property
 * @param warned      violating runs warned before their violation
 * @param falseAlarms runs that held but were warned
 * @param medianLead  the median time from the warning to the violation over the warned runs, in {@code unit}; NaN
 *                    when no run was warned
 * @param unit        what the times count: {@code s} or {@code ticks}
 * @param brier       the Brier score of the calibrated forecast (each run weighs the same, its forecasts sharing one
 *                    unit of weight; 0 is perfect)
 * @param baseBrier   the same for always saying the training runs' share of violations
 * @param counted     what {@code runs} counts: {@value #RUNS}, or {@value #OBLIGATIONS} for a deadline forecast,
 *                    where each obligation is judged (it missed its deadline or it was met)
 * @param rule        the rule scored, in words ({@value #FORECAST} for the learned rule)
 * @param baseline    the property's baseline scored on the same cases, or null (scorecards written before it)
 * @param baselineChosen whether the baseline warns in place of the learned rule, which did worse on the same folds
 */
public record Scorecard(String property, int folds, int runs, int violating, int warned, int falseAlarms,
                        double medianLead, String unit, double brier, double baseBrier, String counted, String rule,
                        Scorecard baseline, boolean baselineChosen) {

    /** The learned rule's words. */
    public static final String FORECAST = "the forecast's warning rule";
    /** A bound's baseline. */
    public static final String RAW_VALUE = "raw value: warn below the lowest reading of any safe training run";
    /** A deadline's baseline. */
    public static final String ELAPSED = "elapsed time: warn once pending longer than every training obligation";

    /**
     * What a scorecard names besides its figures.
     *
     * @param baseline the baseline's words
     */
    public record Names(String property, String unit, String counted, String rule, String baseline) {

        /** The same names for the rule {@code r}. */
        public Names withRule(String r) {
            return new Names(property, unit, counted, r, baseline);
        }
    }

    /** A scorecard of the learned rule without a baseline beside it. */
    public Scorecard(String property, int folds, int runs, int violating, int warned, int falseAlarms,
                     double medianLead, String unit, double brier, double baseBrier, String counted) {
        this(property, folds, runs, violating, warned, falseAlarms, medianLead, unit, brier, baseBrier, counted,
                FORECAST, null, false);
    }

    /** The rule in force: the baseline's scorecard when it was chosen, else this one. */
    public Scorecard inForce() {
        return baselineChosen && baseline != null ? baseline : this;
    }

    /** A scorecard over runs. */
    public static final String RUNS = "runs";
    /** A scorecard over the obligations of a bounded-response property. */
    public static final String OBLIGATIONS = "obligations";

    public Scorecard {
        if (!RUNS.equals(counted) && !OBLIGATIONS.equals(counted)) {
            throw new IllegalArgumentException("a scorecard counts runs or obligations, not " + counted);
        }
        if (baselineChosen && baseline == null) {
            throw new IllegalArgumentException("a baseline chosen needs its scorecard");
        }
    }

    /** A scorecard over runs. */
    public Scorecard(String property, int folds, int runs, int violating, int warned, int falseAlarms,
                     double medianLead, String unit, double brier, double baseBrier) {
        this(property, folds, runs, violating, warned, falseAlarms, medianLead, unit, brier, baseBrier, RUNS);
    }

    /** The runs that held. */
    public int held() {
        return runs - violating;
    }

    /** Whether the forecast scores better than the base rate: it knows more than how often runs violate. */
    public boolean skill() {
        return brier < baseBrier;
    }

    /** The median of {@code leads} (NaN when empty). */
    public static double median(List<Double> leads) {
        if (leads.isEmpty()) {
            return Double.NaN;
        }
        double[] sorted = leads.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        int mid = sorted.length / 2;
        return sorted.length % 2 == 1 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
    }

    /**
     * The scorecard in two lines, as {@code learn} and {@code watch} print it, and with a baseline a third: the
     * baseline on the same folds, and which of the two warns.
     */
    public List<String> lines() {
        if (baseline == null) {
            return ownLines();
        }
        List<String> all = new ArrayList<>(ownLines());
        all.add(String.format(Locale.ROOT, "  baseline on the same folds, %s: warned %d of %d, %d false alarm(s), %s;"
                        + " %s", baseline.rule, baseline.warned, baseline.violating, baseline.falseAlarms,
                baseline.leadWords(), baselineChosen ? "the baseline warns (the forecast's rule did worse on the folds)"
                        : "the forecast's rule warns (at least as good as the baseline on the folds)"));
        return List.copyOf(all);
    }

    private List<String> ownLines() {
        boolean runsCounted = RUNS.equals(counted);
        String first = String.format(Locale.ROOT, "scorecard of '%s' (%d-fold cross-validation on %d %s): warned "
                + "%d of %d %s, %d false alarm(s) in %d %s, %s", property, folds, runs, counted, warned,
                violating, runsCounted ? "violations" : "missed deadlines", falseAlarms, held(),
                runsCounted ? "safe runs" : "met in time", leadWords());
        String often = runsCounted ? "runs violate" : "deadlines are missed";
        String second = Double.isNaN(brier) ? "  no Brier score: no held-out forecast had evidence (the forecast has"
                + " no skill to show)" : String.format(Locale.ROOT, "  Brier score %.3f vs %.3f for the base rate: %s",
                brier, baseBrier, skill() ? "the forecast knows more than how often " + often
                        : "the forecast has no skill on these models (it does no better than the base rate)");
        return List.of(first, second);
    }

    /**
     * One sentence for the live page: "these models warned 2 of 11 violations in cross-validation, 1 false alarm in
     * 32 safe runs; Brier 0.193 vs base rate 0.191".
     */
    public String summary() {
        boolean runsCounted = RUNS.equals(counted);
        return String.format(Locale.ROOT, "these models warned %d of %d %s in cross-validation, %d false "
                + "alarm(s) in %d %s; Brier %.3f vs base rate %.3f", warned, violating,
                runsCounted ? "violations" : "missed deadlines", falseAlarms, held(),
                runsCounted ? "safe runs" : "obligations met in time", brier, baseBrier);
    }

    private String leadWords() {
        if (Double.isNaN(medianLead)) {
            return "no lead";
        }
        return "s".equals(unit) ? String.format(Locale.ROOT, "median lead %.1f s", medianLead)
                : String.format(Locale.ROOT, "median lead %.0f %s", medianLead, unit);
    }
}
