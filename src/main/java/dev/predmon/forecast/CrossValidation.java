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
 * <em>optional clauses</em> (a bound's: the thesis's matching). Rules are compared by their wrong calls (a false alarm
 * and a missed violation cost the same), then by the violations they warn ahead (at the same cost, the rule that warns
 * more: a missed violation cannot be taken back), then by their median lead. Each variant and each set of optional
 * clauses is tried with the threshold chosen for it; the best set wins, the fewest optional clauses on a tie (a clause
 * earns its place), and the earliest variant that does as well as the baseline.
 *
 * <p>The learned rule is scored out of fold: each fold is judged by the rule learned from the other folds only. Its
 * <em>baseline</em> (a one-line rule that needs no machine: the raw value against the lowest safe training reading,
 * the time pending against every training obligation) is scored on the same cases. The learned rule is chosen where
 * it is at least as good as the baseline: it warns at least as many violations ahead, and where it warns no more of
 * them, it raises no more false alarms and its median lead is no shorter (the baseline's recall, at the baseline's
 * false alarms). Else the baseline alone warns. Where the learned rule warns more violations, the false alarms that
 * come with them are those its threshold was chosen to trade for them (never below even odds), and both scorecards
 * are printed side by side.
 *
 * <p>A baseline that says the same of every case of a fold (the base rate of an absence or a precedence, which warns
 * every run where the fold's training runs violated at even odds or more, else none) is compared by {@link #compare}
 * instead: fewer wrong calls, then more violations warned, then the longer lead. Recall first would hand it every tie
 * it cannot lose: warning every run, it warns every violation, and a learned rule that missed one would lose to it
 * however many false alarms it saved.
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
     * @param why       how it was chosen, in one line, without the threshold
     */
    public record Rule(Calibration calibration, double threshold, boolean validated, int variant, List<Boolean> kept,
                       String why) {

        public Rule {
            kept = List.copyOf(kept);
        }

        /** How it was chosen, after its threshold: {@code 0.94 by cross-validation ...}, {@code default 0.50: ...}. */
        public String note() {
            return String.format(Locale.ROOT, validated ? "%.2f %s" : "default %.2f: %s", threshold, why);
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
     * Every variant and optional clause the cross-validation may choose from, and what the baseline is.
     *
     * @param what             what a case is, for the notes: {@code runs} or {@code obligations}
     * @param constantBaseline whether the baseline says the same of every case of a fold (the base rate: warn every
     *                         run or none), so that it is compared by wrong calls ({@link #compare}), not recall first
     */
    public record Space(int variants, int optional, String what, boolean constantBaseline) {

        /** A space whose baseline reads the case (the raw value, the time pending): compared recall first. */
        public Space(int variants, int optional, String what) {
            this(variants, optional, what, false);
        }
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
        boolean baseline = space.constantBaseline() ? compare(learned, base) < 0 : worse(learned, base);
        Scorecard baseCard = base.scorecard(card.withRule(card.baseline()), folds, cases.size(), null, false);
        Scorecard learnedCard = learned.scorecard(card, folds, cases.size(), baseCard, baseline);
        return new Choice(rule, baseline, learnedCard);
    }

    /**
     * Whether {@code learned} did worse than its baseline {@code base} on the same cases: fewer violations warned
     * ahead; or as many and more false alarms; or as many of both and a shorter median lead. Where the models add no
     * warned violation, the rule must add no false alarm and give away no lead.
     */
    static boolean worse(Tally learned, Tally base) {
        if (learned.warned != base.warned) {
            return learned.warned < base.warned;
        }
        if (learned.alarms != base.alarms) {
            return learned.alarms > base.alarms;
        }
        return compareLeads(learned, base) < 0;
    }

    /**
     * The order of rules on the same cases, positive when {@code a} is better: fewer wrong calls, then more violations
     * warned ahead, then a longer median lead (a rule with a lead before one without); 0 when they tie on all three.
     */
    static int compare(Tally a, Tally b) {
        if (a.errors() != b.errors()) {
            return a.errors() < b.errors() ? 1 : -1;
        }
        if (a.warned != b.warned) {
            return a.warned > b.warned ? 1 : -1;
        }
        return compareLeads(a, b);
    }

    /** Positive when {@code a}'s median lead is the longer (a rule with a lead before one without), 0 on a tie. */
    private static int compareLeads(Tally a, Tally b) {
        double la = Scorecard.median(a.leads);
        double lb = Scorecard.median(b.leads);
        if (Double.isNaN(la) || Double.isNaN(lb)) {
            return Double.isNaN(la) == Double.isNaN(lb) ? 0 : Double.isNaN(la) ? -1 : 1;
        }
        return Double.compare(la, lb);
    }

    /**
     * The rule {@code cases} learn. Each variant is tried with every set of optional clauses, the best set kept (by
     * {@link #compare}, then fewer clauses: a clause earns its place). Of the variants, the earliest one that makes no
     * more wrong calls on the cases than the baseline is kept: a later warning (a wider margin) is bought with the
     * lead, which cases without a violation cannot measure, so it must be needed to do as well as the one-line rule.
     * When no variant does as well, the best by {@link #compare}.
     */
    static Rule fit(List<Case> cases, Space space) {
        Calibration calibration = Calibration.fit(cases.stream()
                .map(c -> new Calibration.Sample(c.probabilities(), c.violated())).toList());
        Tally baseline = new Tally();
        cases.forEach(c -> baseline.add(c, c.baselineAt(), null));
        Rule chosen = null;
        Tally chosenTally = null;
        for (int v = 0; v < Math.max(1, space.variants()); v++) {
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
                int order = best == null ? 1 : compare(t, bestTally);
                if (order > 0 || (order == 0 && n < bestKept)) {
                    best = r;
                    bestTally = t;
                    bestKept = n;
                }
            }
            if (bestTally.errors() <= baseline.errors()) {
                return best; // the earliest variant that does as well as the baseline
            }
            if (chosen == null || compare(bestTally, chosenTally) > 0) {
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
        return new Rule(c.validated() ? calibration : Calibration.IDENTITY, c.threshold(), c.validated(), variant, kept,
                c.note());
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
