package dev.predmon.forecast;

import java.util.List;

/**
 * When the deadline forecast of one bounded-response property warns: the probability of a miss at or above which it
 * does, chosen by cross-validation over the training obligations ({@link ThresholdChoice}), the calibration of
 * {@link Survival}'s estimate fitted on the same held-out forecasts, and the novelty clause: an obligation pending
 * longer than every training obligation (no evidence either way) is warned once half of the time from the longest of
 * them to the deadline has passed too, so that a robot stuck in a way no training run was is warned with that half of
 * the margin left.
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
 */
public record DeadlineRule(double threshold, String note, boolean validated, Calibration calibration, double margin,
                           boolean baseline) {

    /** The novelty clause's margin before the cross-validation chose one: half of it. */
    public static final double HALF = 0.5;
    /** The margins the cross-validation chooses from, earliest first. */
    public static final List<Double> MARGINS = List.of(0.0, HALF);

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
        return new DeadlineRule(NEVER, why + "; not validated: the probability is shown but does not warn, the warning"
                + " comes past every training obligation", false, Calibration.IDENTITY, margin, baseline);
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
        return e.novel() ? pastEveryObligation(elapsed, deadline, survival, margin)
                : calibration.apply(e.probability()) >= threshold;
    }

    /** As above, with one curve for both (no input of its own). */
    public boolean warns(Survival.Estimate e, double elapsed, double deadline, Survival survival) {
        return warns(e, elapsed, deadline, survival, survival);
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
