package dev.predmon.forecast;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The one cross-validation that chooses every property's warning rule, on held-out cases (runs of a bound, obligations
 * of a deadline) each forecast by the models of a fold learned without it.
 *
 * <p>A rule is learned from cases: a calibration of the raw forecast ({@link Calibration#fit}), a threshold on the
 * calibrated scale ({@link ThresholdChoice}), one of the property's <em>variants</em> of its clause that warns
 * whatever the probability (a bound's: beyond the safe training runs and below their lowest value; a deadline's: past
 * every training obligation from the same input, at once or with half of the margin left), and any of its
 * <em>optional clauses</em> (a bound's: the thesis's matching). Each variant and each set of optional clauses is
 * tried with the threshold chosen for it; the fewest wrong calls win, then the longest median lead, then the fewest
 * optional clauses and the earliest variant: a clause is kept only where it does better on the cases than the rule
 * without it (it earns its place).
 *
 * <p>The learned rule is scored out of fold: each fold is judged by the rule learned from the other folds only. Its
 * <em>baseline</em> (a one-line rule that needs no machine: the raw value against the lowest safe training reading,
 * the time pending against every training obligation) is scored on the same cases. The learned rule is chosen only
 * where it does at least as well: no more wrong calls, and with as many, no shorter median lead. Else the baseline is.
 */
public final class CrossValidation {

    private CrossValidation() {
    }

    /**
     * One held-out case.
     *
     * @param fold          its fold
     * @param violated      whether it violated the property (missed its deadline)
     * @param violationTime when (ignored when it held)
     * @param probabilities its raw forecasts that had evidence, in order
     * @param times         when each was made
     * @param variants      per variant of the property's clause, when it first warned the case (NaN: never)
     * @param optional      per optional clause, when it first warned the case (NaN: never)
     * @param baselineAt    when the baseline first warned it (NaN: never)
     * @param baseRate      the base rate of the fold's training cases
     */
    public record Case(int fold, boolean violated, double violationTime, List<Double> probabilities,
                       List<Double> times, List<Double> variants, List<Double> optional, double baselineAt,
                       double baseRate) {

        public Case {
            probabilities = List.copyOf(probabilities);
            times = List.copyOf(times);
            variants = List.copyOf(variants);
            optional = List.copyOf(optional);
        }

        double peak() {
            return probabilities.stream().mapToDouble(p -> p).max().orElse(0);
        }

        /** When the clauses of {@code variant} and {@code kept} warned it first, NaN when none did. */
        double caughtAt(int variant, List<Boolean> kept) {
            double at = variants.isEmpty() ? Double.NaN : variants.get(variant);
            for (int i = 0; i < optional.size() && i < kept.size(); i++) { // a clause not offered is not kept
                if (kept.get(i)) {
                    at = earliest(at, optional.get(i));
                }
            }
            return at;
        }
    }

    /**
     * A learned rule: its calibration and threshold, its variant and the optional clauses it keeps.
     *
     * @param validated whether held-out cases of both outcomes chose the threshold
     * @param note      how it was chosen, in one line
     */
    public record Rule(Calibration calibration, double threshold, boolean validated, int variant, List<Boolean> kept,
                       String note) {

        public Rule {
            kept = List.copyOf(kept);
        }

        /** Whether it keeps optional clause {@code i}. */
        public boolean keeps(int i) {
            return i < kept.size() && kept.get(i);
        }

        /** When this rule first warns {@code c}: its first calibrated forecast at the threshold or a clause. */
        double warnedAt(Case c) {
            double at = c.caughtAt(variant, kept);
            for (int i = 0; i < c.probabilities().size(); i++) {
                if (calibration.apply(c.probabilities().get(i)) >= threshold) {
                    return earliest(at, c.times().get(i));
                }
            }
            return at;
        }
    }

    /**
     * What the cross-validation chose.
     *
     * @param rule      the learned rule, fitted on every case
     * @param baseline  whether the baseline is chosen instead (the learned rule did worse on the folds)
     * @param scorecard the learned rule's out-of-fold scorecard, with the baseline's beside it; null without a case
     */
    public record Choice(Rule rule, boolean baseline, Scorecard scorecard) {
    }

    /**
     * Every variant and optional clause the cross-validation may choose from.
     *
     * @param what what a case is, for the notes: {@code runs} or {@code obligations}
     */
    public record Space(int variants, int optional, String what) {
    }

    /**
     * Chooses on {@code cases} from {@code folds} folds.
     *
     * @param card what the scorecard names: the property, the unit, what a case is and the baseline's words
     */
    public static Choice choose(List<Case> cases, int folds, Space space, Scorecard.Names card) {
        Rule rule = fit(cases, space);
        if (cases.isEmpty()) {
            return new Choice(rule, false, null);
        }
        Tally learned = new Tally();
        Tally base = new Tally();
        for (int f = 0; f < folds; f++) {
            int fold = f;
            List<Case> in = cases.stream().filter(c -> c.fold() == fold).toList();
            if (in.isEmpty()) {
                continue;
            }
            Rule r = fit(cases.stream().filter(c -> c.fold() != fold).toList(), space);
            in.forEach(c -> learned.add(c, r.warnedAt(c), r.calibration()));
            in.forEach(c -> base.add(c, c.baselineAt(), null));
        }
        boolean baseline = worse(learned, base);
        Scorecard baseCard = base.scorecard(card.withRule(card.baseline()), folds, cases.size(), null, false);
        Scorecard learnedCard = learned.scorecard(card, folds, cases.size(), baseCard, baseline);
        return new Choice(rule, baseline, learnedCard);
    }

    /** Whether {@code learned} did worse than {@code base}: more wrong calls, or as many and a shorter lead. */
    static boolean worse(Tally learned, Tally base) {
        int a = learned.errors();
        int b = base.errors();
        if (a != b) {
            return a > b;
        }
        double la = Scorecard.median(learned.leads);
        double lb = Scorecard.median(base.leads);
        return !Double.isNaN(lb) && (Double.isNaN(la) || la < lb);
    }

    /**
     * The rule {@code cases} learn. Each variant is tried with every set of optional clauses, the best set kept (fewer
     * wrong calls, then a longer lead, then fewer clauses: a clause earns its place). Of the variants, the earliest one
     * that makes no more wrong calls on the cases than the baseline is kept: a later warning (a wider margin) is bought
     * with the lead, which cases without a violation cannot measure, so it must be needed to do as well as the
     * one-line rule. When no variant does as well, the one with the fewest wrong calls (then the longest lead).
     */
    static Rule fit(List<Case> cases, Space space) {
        Calibration calibration = Calibration.fit(cases.stream()
                .map(c -> new Calibration.Sample(c.probabilities(), c.violated())).toList());
        Tally baseline = new Tally();
        cases.forEach(c -> baseline.add(c, c.baselineAt(), null));
        Rule chosen = null;
        Tally chosenTally = null;
        int variants = Math.max(1, space.variants());
        for (int v = 0; v < variants; v++) {
            Rule best = null;
            Tally bestTally = null;
            int bestKept = 0;
            for (int mask = 0; mask < 1 << space.optional(); mask++) {
                List<Boolean> kept = new ArrayList<>();
                for (int i = 0; i < space.optional(); i++) {
                    kept.add((mask & (1 << i)) != 0);
                }
                Rule r = rule(cases, space, calibration, v, kept);
                Tally t = new Tally();
                cases.forEach(x -> t.add(x, r.warnedAt(x), r.calibration()));
                int n = Integer.bitCount(mask);
                if (best == null || better(t, n, bestTally, bestKept)) {
                    best = r;
                    bestTally = t;
                    bestKept = n;
                }
            }
            if (bestTally.errors() <= baseline.errors()) {
                return best; // the earliest variant that does as well as the baseline
            }
            if (chosen == null || better(bestTally, 0, chosenTally, 0)) {
                chosen = best;
                chosenTally = bestTally;
            }
        }
        return chosen;
    }

    /** The rule of {@code variant} and {@code kept} with its threshold chosen on {@code cases}. */
    private static Rule rule(List<Case> cases, Space space, Calibration calibration, int variant,
                             List<Boolean> kept) {
        ThresholdChoice.Choice c = ThresholdChoice.choose(cases.stream().map(x -> new ThresholdChoice.Peak(
                calibration.apply(x.peak()), x.violated(), before(x.caughtAt(variant, kept), x))).toList(),
                space.what());
        return c.validated()
                ? new Rule(calibration, c.threshold(), true, variant, kept,
                String.format(Locale.ROOT, "%.2f %s", c.threshold(), c.note()))
                : new Rule(Calibration.IDENTITY, c.threshold(), false, variant, kept, c.note());
    }

    /** Fewer wrong calls, then a longer median lead, then fewer optional clauses (earlier variants come first). */
    private static boolean better(Tally t, int kept, Tally best, int bestKept) {
        if (t.errors() != best.errors()) {
            return t.errors() < best.errors();
        }
        double a = Scorecard.median(t.leads);
        double b = Scorecard.median(best.leads);
        if (!Double.isNaN(a) && (Double.isNaN(b) || a > b)) {
            return true;
        }
        if (!Double.isNaN(b) && (Double.isNaN(a) || a < b)) {
            return false;
        }
        return kept < bestKept;
    }

    private static boolean before(double at, Case c) {
        return !Double.isNaN(at) && (!c.violated() || at < c.violationTime());
    }

    static double earliest(double a, double b) {
        return Double.isNaN(a) ? b : Double.isNaN(b) ? a : Math.min(a, b);
    }

    /** Adds up cases judged by one rule. */
    static final class Tally {
        private int violating;
        private int warned;
        private int alarms;
        private int scored;
        private double brier;
        private double base;
        private final List<Double> leads = new ArrayList<>();

        /**
         * {@code c} warned at {@code at} (NaN: never); its calibrated forecasts scored, or the base rate for a rule
         * without a forecast ({@code calibration} null).
         */
        void add(Case c, double at, Calibration calibration) {
            double y = c.violated() ? 1 : 0;
            if (!c.probabilities().isEmpty()) {
                double sum = 0;
                for (double p : c.probabilities()) {
                    double q = calibration == null ? c.baseRate() : calibration.apply(p);
                    sum += (q - y) * (q - y);
                }
                brier += sum / c.probabilities().size();
                base += (c.baseRate() - y) * (c.baseRate() - y);
                scored++;
            }
            boolean warning = !Double.isNaN(at) && (!c.violated() || at < c.violationTime());
            if (c.violated()) {
                violating++;
                if (warning) {
                    warned++;
                    leads.add(c.violationTime() - at);
                }
            } else if (!Double.isNaN(at)) {
                alarms++;
            }
        }

        int errors() {
            return violating - warned + alarms;
        }

        Scorecard scorecard(Scorecard.Names n, int folds, int cases, Scorecard baseline, boolean baselineChosen) {
            return new Scorecard(n.property(), folds, cases, violating, warned, alarms, Scorecard.median(leads),
                    n.unit(), scored == 0 ? Double.NaN : brier / scored, scored == 0 ? Double.NaN : base / scored,
                    n.counted(), n.rule(), baseline, baselineChosen);
        }

    }
}
