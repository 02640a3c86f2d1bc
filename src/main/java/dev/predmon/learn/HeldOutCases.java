package dev.predmon.learn;

import dev.predmon.forecast.CrossValidation;
import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.Survival;
import dev.predmon.forecast.ThresholdChoice;
import dev.predmon.replay.ReplayedRun;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleUnaryOperator;

/**
 * The held-out replays ({@link HeldOutFolds}) as the cases the one cross-validation chooses every rule on
 * ({@link CrossValidation}): a bound's runs, a deadline's obligations, each with when its rule's clauses and its
 * baseline first warned it.
 */
final class HeldOutCases {

    private HeldOutCases() {
    }

    /**
     * Held-out run {@code h} of a bound property, in fold {@code fold} whose training runs had base rate
     * {@code baseRate} and whose safe training runs went as low as {@code floor} (on the forecast's scale; {@code scale}
     * turns a value as the property reads it into that scale).
     *
     * <p>Its variant is the clause beyond the safe training runs (novel, or no nominal machine left, and below
     * {@code floor}): the replay's warnings by it, or a forecast of a novel run below the floor, whichever came first.
     * Its optional clause is the thesis's matching. Its baseline, the raw-value rule, warns a run that held at its
     * first reading below the floor, and a violating run from the start of the stretch below the floor that lasted up
     * to its violation (a stretch that ended before it warned of nothing that came).
     */
    static CrossValidation.Case bound(int fold, HeldOutRun h, double baseRate, double floor,
                                      DoubleUnaryOperator scale) {
        double novelty = h.noveltyAt();
        double first = Double.NaN;
        double stretch = Double.NaN;
        for (int i = 0; i < h.values().size(); i++) {
            double v = scale.applyAsDouble(h.values().get(i));
            if (Double.isNaN(v)) {
                continue;
            }
            double t = h.times().get(i);
            if (v < floor) {
                first = Double.isNaN(first) ? t : first;
                stretch = Double.isNaN(stretch) ? t : stretch;
                if (h.novel().get(i) && !(novelty <= t)) {
                    novelty = t;
                }
            } else {
                stretch = Double.NaN;
            }
        }
        double baseline = h.violated() ? stretch : first;
        List<Double> ps = new ArrayList<>();
        List<Double> ts = new ArrayList<>();
        for (int i = 0; i < h.probabilities().size(); i++) {
            if (i >= h.novel().size() || !h.novel().get(i)) { // the threshold speaks only where a model fits
                ps.add(h.probabilities().get(i));
                ts.add(h.times().get(i));
            }
        }
        double clause = Double.isNaN(novelty) ? baseline : Double.isNaN(baseline) ? novelty : Math.min(novelty, baseline);
        return new CrossValidation.Case(fold, h.violated(), h.violationTime(), ps, ts, List.of(clause),
                List.of(h.matchingAt()), baseline, baseRate);
    }

    /**
     * Held-out run {@code h} of an absence or a precedence, in a fold whose training runs violated it at the rate
     * {@code baseRate}. It has no variant and no optional clause: its forecast's probability alone warns. Its baseline,
     * always saying the base rate, warns it at its first forecast where that rate is at even odds or more, and never
     * where it is not.
     */
    static CrossValidation.Case event(int fold, HeldOutRun h, double baseRate) {
        double baseline = baseRate >= ThresholdChoice.DEFAULT && !h.times().isEmpty() ? h.times().get(0) : Double.NaN;
        return new CrossValidation.Case(fold, h.violated(), h.violationTime(), h.probabilities(), h.times(),
                List.of(), List.of(), baseline, baseRate);
    }

    /**
     * Held-out obligation {@code o}, forecast in its fold by the curve of its trigger's input, {@code pooled} being
     * every training obligation of its property in the fold. Its times are how long it had been pending. Its variants
     * ({@link DeadlineRule#variants}) are the late clause at each level of {@link DeadlineRule#LEVELS} and each ceiling:
     * its first forecast pending past that prediction bound of its curve ({@link DeadlineRule#pastLate}); then the novelty clause
     * at each margin of {@link DeadlineRule#MARGINS}: pending past every training obligation from the same input (its
     * first forecast that says so), and that share of the time from there to the deadline passed too. Its baseline,
     * the elapsed-time rule, warns once it is pending longer than every obligation of {@code pooled}.
     */
    static CrossValidation.Case deadline(int fold, ReplayedRun.Obligation o, Survival pooled) {
        double deadline = o.property().within().amount();
        List<Double> ps = new ArrayList<>();
        List<Double> elapsed = new ArrayList<>();
        double novelFrom = Double.NaN;
        double baseline = Double.NaN;
        for (ReplayedRun.Step step : o.forecasts()) {
            if (!step.estimate().novel()) {
                ps.add(step.estimate().probability());
                elapsed.add(step.elapsed());
            } else if (Double.isNaN(novelFrom)) {
                novelFrom = step.elapsed();
            }
            if (Double.isNaN(baseline) && DeadlineRule.pastEvery(step.elapsed(), pooled)) {
                baseline = step.elapsed();
            }
        }
        List<Double> variants = new ArrayList<>();
        for (int v = 0; !Double.isNaN(DeadlineRule.levelOf(v)); v++) {
            double at = Double.NaN;
            for (ReplayedRun.Step step : o.forecasts()) {
                if (o.curve() != null && DeadlineRule.pastLate(step.elapsed(), o.curve(), DeadlineRule.levelOf(v),
                        DeadlineRule.waitedOf(v))) {
                    at = step.elapsed();
                    break;
                }
            }
            variants.add(at);
        }
        for (double margin : DeadlineRule.MARGINS) {
            double at = Double.NaN;
            if (!Double.isNaN(novelFrom)) {
                double due = novelFrom + margin * (deadline - novelFrom);
                for (ReplayedRun.Step step : o.forecasts()) {
                    if (step.estimate().novel() && step.elapsed() >= due) {
                        at = step.elapsed();
                        break;
                    }
                }
            }
            variants.add(at);
        }
        return new CrossValidation.Case(fold, o.missed(), o.duration(), ps, elapsed, variants, List.of(), baseline,
                pooled.missRate(deadline));
    }
}
