package dev.predmon.forecast;

import java.util.List;

/**
 * When the deadline forecast of one bounded-response property warns: the probability of a miss at or above which it
 * does, chosen by cross-validation over the training obligations ({@link ThresholdChoice}), the calibration of
 * {@link Survival}'s estimate fitted on the same held-out forecasts, and a clause that warns whatever the probability.
 * That clause is the <em>late</em> clause where the cross-validation chose a prediction level: an obligation pending
 * past the upper prediction bound of how long the obligations that began where it did (which skill, where to) took
 * ({@link Survival#lateAfter}), so that a leg that usually takes 10 ticks is warned long before one that takes 200;
 * else the novelty clause: an obligation pending longer than every training obligation (no evidence either way) is
 * warned once {@code margin} of the time from the longest of them to the deadline has passed too.
 *
 * <p>Where the training obligations cannot choose (too few logs to cross-validate, or no held-out obligation missed
 * its deadline) the rule is {@link #DEFAULT}: even odds on the raw estimate, and the novelty clause. It is not
 * validated, and says so: no verdict rests on no evidence.
 *
 * @param threshold   the calibrated P(miss) at or above which it warns
 * @param note        how the threshold was chosen, in one line
 * @param validated   whether held-out obligations that missed and that did not chose it
 * @param calibration the map from the estimate to the probability reported ({@link Calibration#IDENTITY} when none
 *                    was fitted); the threshold is on the calibrated scale
 * @param margin      the novelty clause's share of the time from the longest training obligation to the deadline that
 *                    must pass too ({@link #HALF} in rules learned before the cross-validation chose it, 0 to warn as
 *                    soon as the obligation is past every training one from the same input)
 * @param baseline    whether the elapsed-time baseline warns in place of this rule (pending longer than every training
 *                    obligation of the property), because this rule did worse on the same held-out folds
 * @param level       the late clause's prediction level ({@link #LEVELS}), NaN for the novelty clause
 * @param waited      whether the late clause's ceiling is every training obligation, those let go still pending
 *                    included (as the elapsed-time rule's), rather than every one whose response came
 */
public record DeadlineRule(double threshold, String note, boolean validated, Calibration calibration, double margin,
                           boolean baseline, double level, boolean waited) {

    /** The novelty clause's margin before the cross-validation chose one: half of it. */
    public static final double HALF = 0.5;
    /** The margins the cross-validation chooses from, earliest first. */
    public static final List<Double> MARGINS = List.of(0.0, HALF);
    /**
     * The late clause's prediction levels the cross-validation chooses from, earliest first: of 100 and of 1000 legs
     * like the training ones, about one would outlast the bound. A lower level is not offered: a clause that expects
     * one false alarm in twenty legs (a few runs) raises more than an operator keeps listening to, and a few dozen
     * held-out obligations are too few to tell it from one in a hundred.
     */
    public static final List<Double> LEVELS = List.of(0.99, 0.999);

    /**
     * The clauses the cross-validation chooses from, in the order it tries them: the late clause at each of
     * {@link #LEVELS} capped at every discharged training obligation, then at each capped at every training obligation
     * (those let go still pending included: later, where runs ended on the way), then the novelty clause at each of
     * {@link #MARGINS}.
     */
    public static int variants() {
        return 2 * LEVELS.size() + MARGINS.size();
    }

    /** The prediction level of variant {@code v} ({@link #variants}), NaN for a novelty clause. */
    public static double levelOf(int v) {
        return v < 2 * LEVELS.size() ? LEVELS.get(v % LEVELS.size()) : Double.NaN;
    }

    /** Whether variant {@code v}'s late clause is capped at every training obligation, censored ones included. */
    public static boolean waitedOf(int v) {
        return v >= LEVELS.size() && v < 2 * LEVELS.size();
    }

    /** The novelty margin of variant {@code v} ({@link #variants}); 0 for a late clause (not used by it). */
    public static double marginOf(int v) {
        return v < 2 * LEVELS.size() ? 0 : MARGINS.get(v - 2 * LEVELS.size());
    }

    /** A rule whose warning clause is the late clause at {@code level} (NaN: the novelty clause with {@code margin}). */
    public DeadlineRule(double threshold, String note, boolean validated, Calibration calibration, double margin,
                        boolean baseline, double level) {
        this(threshold, note, validated, calibration, margin, baseline, level, false);
    }

    /** A rule whose warning clause is the novelty clause with {@code margin}. */
    public DeadlineRule(double threshold, String note, boolean validated, Calibration calibration, double margin,
                        boolean baseline) {
        this(threshold, note, validated, calibration, margin, baseline, Double.NaN, false);
    }

    /** A rule whose novelty clause waits for half of the margin, as rules learned before the choice do. */
    public DeadlineRule(double threshold, String note, boolean validated, Calibration calibration) {
        this(threshold, note, validated, calibration, HALF, false);
    }

    /** A threshold no probability reaches: a rule with it warns by the novelty clause alone. */
    public static final double NEVER = 2;

    /**
     * The rule of a property whose training obligations chose nothing (too few logs, or no held-out obligation
     * missed): its probability is shown and said to be unvalidated, and it warns by the novelty clause alone, an
     * obligation pending past every training one. A probability no held-out miss ever checked is no evidence to warn
     * on: censored training obligations (runs that ended on the way) hold an estimate at even odds from the start.
     */
    public static final DeadlineRule DEFAULT = unvalidated("not cross-validated");

    /** An unvalidated rule ({@link #DEFAULT}) with {@code why} in its note. */
    public static DeadlineRule unvalidated(String why) {
        return unvalidated(why, false, HALF);
    }

    /** An unvalidated rule whose novelty clause waits for {@code margin}, the baseline in its place if {@code baseline}. */
    public static DeadlineRule unvalidated(String why, boolean baseline, double margin) {
        return unvalidated(why, baseline, margin, Double.NaN);
    }

    /** As above, with the late clause at {@code level} in place of the novelty clause when it is a number. */
    public static DeadlineRule unvalidated(String why, boolean baseline, double margin, double level) {
        return unvalidated(why, baseline, margin, level, false);
    }

    /** As above, the late clause capped at every training obligation, censored ones included, if {@code waited}. */
    public static DeadlineRule unvalidated(String why, boolean baseline, double margin, double level,
                                           boolean waited) {
        return new DeadlineRule(NEVER, why + "; not validated: the probability is shown but does not warn, the warning"
                + (Double.isNaN(level) ? " comes past every training obligation"
                : String.format(java.util.Locale.ROOT, " comes past the %s prediction bound of the training"
                + " obligations that began where it did", percent(level))), false, Calibration.IDENTITY, margin,
                baseline, level, waited);
    }

    /** {@code 0.999} as {@code 99.9%}. */
    public static String percent(double level) {
        return new java.math.BigDecimal(Double.toString(level * 100)).stripTrailingZeros().toPlainString() + "%";
    }

    /**
     * The rule of a held-out replay ({@code learn}'s cross-validation): only the novelty clause warns, so that the
     * obligations it catches are known whatever threshold is chosen after.
     */
    public static final DeadlineRule NOVELTY_ONLY = new DeadlineRule(NEVER, "held out: the novelty clause alone",
            false, Calibration.IDENTITY, 0, false);

    public DeadlineRule {
        if (!((threshold >= 0 && threshold <= 1) || threshold == NEVER)) {
            throw new IllegalArgumentException("a threshold is a probability, from 0 to 1: " + threshold);
        }
        if (!(margin >= 0 && margin <= 1)) {
            throw new IllegalArgumentException("a margin is a share, from 0 to 1: " + margin);
        }
        if (!Double.isNaN(level) && !(level > 0.5 && level < 1)) {
            throw new IllegalArgumentException("a prediction level is above 0.5 and below 1: " + level);
        }
    }

    /** Whether its warning clause is the late clause ({@link #level} a number). */
    public boolean late() {
        return !Double.isNaN(level);
    }

    /** {@code e} with its probability calibrated (a novel estimate has none and stays as it is). */
    public Survival.Estimate calibrated(Survival.Estimate e) {
        if (e.novel()) {
            return e;
        }
        return new Survival.Estimate(calibration.apply(e.probability()), e.timeLeft(), e.atRisk(), e.longer(), false);
    }

    /**
     * Whether the forecast of an obligation pending for {@code elapsed} warns: its calibrated P(miss) reaches the
     * threshold, or it is novel ({@link #pastEveryObligation}); for the baseline, whether it is pending longer than
     * every training obligation of the property ({@link #pastEvery}).
     *
     * @param e        {@code survival}'s raw estimate at {@code elapsed} against {@code deadline}
     * @param survival what the training obligations from the same input did ({@link Survival#at})
     * @param pooled   what every training obligation of the property did
     */
    public boolean warns(Survival.Estimate e, double elapsed, double deadline, Survival survival, Survival pooled) {
        if (baseline) {
            return pastEvery(elapsed, pooled);
        }
        if (late()) {
            return pastLate(elapsed, survival, level, waited)
                    || (!e.novel() && calibration.apply(e.probability()) >= threshold);
        }
        return e.novel() ? pastEveryObligation(elapsed, deadline, survival, margin)
                : calibration.apply(e.probability()) >= threshold;
    }

    /** As above, with one curve for both (no input of its own). */
    public boolean warns(Survival.Estimate e, double elapsed, double deadline, Survival survival) {
        return warns(e, elapsed, deadline, survival, survival);
    }

    /**
     * The late clause: pending longer than the {@code level} prediction bound of the obligations of {@code survival}
     * (the curve of those that began where this one did, {@link Survival#lateAfter}).
     */
    public static boolean pastLate(double elapsed, Survival survival, double level, boolean waited) {
        double late = survival.lateAfter(level, waited);
        return !Double.isNaN(late) && elapsed > late;
    }

    /** The late clause capped at every discharged training obligation. */
    public static boolean pastLate(double elapsed, Survival survival, double level) {
        return pastLate(elapsed, survival, level, false);
    }

    /** The elapsed-time baseline: pending longer than every obligation of {@code survival}. */
    public static boolean pastEvery(double elapsed, Survival survival) {
        return survival.size() > 0 && survival.pendingAfter(elapsed) == 0 && elapsed > survival.longest();
    }

    /**
     * The novelty clause: pending longer than every training obligation, and {@code margin} of the time from the
     * longest of them to the deadline has passed too.
     */
    public static boolean pastEveryObligation(double elapsed, double deadline, Survival survival, double margin) {
        double longest = survival.longest();
        return pastEvery(elapsed, survival) && elapsed >= longest + margin * (deadline - longest);
    }

    /** The novelty clause with half of the margin, as rules learned before the choice warn. */
    public static boolean pastEveryObligation(double elapsed, double deadline, Survival survival) {
        return pastEveryObligation(elapsed, deadline, survival, HALF);
    }
}
