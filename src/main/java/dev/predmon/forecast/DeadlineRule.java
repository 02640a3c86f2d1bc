package dev.predmon.forecast;

import java.util.Locale;

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
 */
public record DeadlineRule(double threshold, String note, boolean validated, Calibration calibration) {

    /** The rule of a property whose training obligations chose nothing: even odds and the novelty clause. */
    public static final DeadlineRule DEFAULT = new DeadlineRule(ThresholdChoice.DEFAULT,
            String.format(Locale.ROOT, "default %.2f: not cross-validated", ThresholdChoice.DEFAULT), false,
            Calibration.IDENTITY);

    /** A threshold no probability reaches: a rule with it warns by the novelty clause alone. */
    public static final double NEVER = 2;

    /**
     * The rule of a held-out replay ({@code learn}'s cross-validation): only the novelty clause warns, so that the
     * obligations it catches are known whatever threshold is chosen after.
     */
    public static final DeadlineRule NOVELTY_ONLY = new DeadlineRule(NEVER, "held out: the novelty clause alone",
            false, Calibration.IDENTITY);

    public DeadlineRule {
        if (!((threshold >= 0 && threshold <= 1) || threshold == NEVER)) {
            throw new IllegalArgumentException("a threshold is a probability, from 0 to 1: " + threshold);
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
     * threshold, or it is novel ({@link #pastEveryObligation}).
     *
     * @param e        {@code survival}'s raw estimate at {@code elapsed} against {@code deadline}
     * @param survival what the training obligations did
     */
    public boolean warns(Survival.Estimate e, double elapsed, double deadline, Survival survival) {
        return e.novel() ? pastEveryObligation(elapsed, deadline, survival)
                : calibration.apply(e.probability()) >= threshold;
    }

    /**
     * The novelty clause: pending longer than every training obligation, and half of the time from the longest of
     * them to the deadline has passed too.
     */
    public static boolean pastEveryObligation(double elapsed, double deadline, Survival survival) {
        return survival.pendingAfter(elapsed) == 0 && elapsed >= (survival.longest() + deadline) / 2;
    }
}
