package dev.predmon.learn;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.Calibration;
import dev.predmon.forecast.CrossValidation;
import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.Scorecard;
import dev.predmon.forecast.Survival;
import dev.predmon.property.Property;
import dev.predmon.property.Response;
import dev.predmon.replay.ReplayedRun;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Learns when the deadline forecast of each bounded-response property warns, by the one cross-validation that chooses
 * every property's rule ({@link CrossValidation}), on the replays the bounds are chosen on ({@link HeldOutFolds}): for
 * each fold, the durations of the other folds' obligations make the {@link Survival} curves of the fold's models (by
 * the trigger's input where an input has enough of them), and each held-out obligation is forecast as {@code watch}'s
 * own monitor forecast it in the replay of its log with them ({@link ReplayedRun#obligations}). The cross-validation
 * chooses the threshold, the calibration and the novelty clause's margin, and scores the rule beside the elapsed-time
 * baseline (pending longer than every training obligation of the property) on the same obligations; where the rule
 * did worse, the baseline warns.
 *
 * <p>An obligation let go before its deadline (its run ended, or its scope closed) has no known outcome and is left
 * out. Where the held-out obligations cannot choose a threshold (too few logs, or none missed its deadline), the
 * threshold stays the default, not validated, and the note says why; the clauses and the baseline are still chosen
 * on the obligations met in time (their false alarms), and the property gets no scorecard: there is no warning of a
 * miss to score.
 */
public final class DeadlineTraining {

    private DeadlineTraining() {
    }

    /**
     * {@code model} with the deadline rule of every property it learned obligations for, chosen on {@code heldOut},
     * the cross-validation's replays of its training logs ({@link ForecastTraining#heldOut}), and their scorecards
     * by property.
     */
    public static ForecastModel train(ForecastModel model, HeldOutFolds heldOut, Abstraction abstraction) {
        Map<String, Response> responses = new TreeMap<>();
        for (Property p : abstraction.properties()) {
            if (p instanceof Response r && model.obligations().containsKey(r.id())
                    && model.obligations().get(r.id()).size() > 0) { // none learned: no forecast to choose a rule for
                responses.put(r.id(), r);
            }
        }
        if (responses.isEmpty()) {
            return model;
        }
        int k = heldOut.folds();
        Map<String, DeadlineRule> rules = new TreeMap<>();
        Map<String, List<Scorecard>> cards = new TreeMap<>();
        for (Response r : responses.values()) {
            if (k < 2) {
                rules.put(r.id(), DeadlineRule.unvalidated("too few logs to cross-validate"));
                continue;
            }
            List<CrossValidation.Case> cases = cases(r.id(), heldOut);
            if (cases.isEmpty()) {
                rules.put(r.id(), DeadlineRule.unvalidated("no held-out obligation was met or missed"));
                continue;
            }
            CrossValidation.Choice c = CrossValidation.choose(cases, k, new CrossValidation.Space(
                    DeadlineRule.variants(), 0, Scorecard.OBLIGATIONS), new Scorecard.Names(r.name(),
                    r.within().unit().key, Scorecard.OBLIGATIONS, Scorecard.FORECAST, Scorecard.ELAPSED));
            rules.put(r.id(), rule(c));
            if (cases.stream().anyMatch(CrossValidation.Case::violated)) {
                cards.put(r.id(), List.of(c.scorecard())); // without a missed deadline there is no warning to score (the note says so)
            }
        }
        return model.withDeadlines(rules).withDeadlineScorecards(cards);
    }

    /**
     * Every held-out obligation of property {@code id} with a known outcome, as the one cross-validation judges it
     * ({@link HeldOutCases#deadline}).
     */
    static List<CrossValidation.Case> cases(String id, HeldOutFolds heldOut) {
        List<CrossValidation.Case> cases = new ArrayList<>();
        for (HeldOutFolds.Fold fold : heldOut.judged()) {
            Survival pooled = fold.obligations().get(id);
            if (pooled == null || pooled.size() == 0) {
                continue; // watch gives no forecast without a training obligation: nothing to judge
            }
            for (HeldOutRun run : fold.runs()) {
                for (ReplayedRun.Obligation o : run.obligations()) {
                    if (o.property().id().equals(id) && (o.discharged() || o.missed())) {
                        cases.add(HeldOutCases.deadline(fold.index(), o, pooled));
                    }
                }
            }
        }
        return cases;
    }

    /**
     * The rule {@code c} chose: the threshold, calibration and novelty margin learned on every held-out obligation, and
     * whether the elapsed-time baseline warns in its place.
     */
    static DeadlineRule rule(CrossValidation.Choice c) {
        CrossValidation.Rule x = c.rule();
        if (!x.validated()) {
            // why, without the choice's default threshold: an unvalidated deadline rule never warns on a probability
            return DeadlineRule.unvalidated(x.why(), c.baseline(),
                    DeadlineRule.marginOf(x.variant()), DeadlineRule.levelOf(x.variant()),
                    DeadlineRule.waitedOf(x.variant()));
        }
        String note = x.note();
        if (c.baseline()) {
            note += "; the elapsed-time baseline warns: the forecast's rule did worse on the same folds";
        }
        return new DeadlineRule(x.threshold(), note, x.validated(),
                x.validated() ? x.calibration() : Calibration.IDENTITY, DeadlineRule.marginOf(x.variant()),
                c.baseline(), DeadlineRule.levelOf(x.variant()), DeadlineRule.waitedOf(x.variant()));
    }

    /**
     * One held-out obligation as its fold's training obligations forecast it: its raw P(miss) at each step that had
     * evidence and how long it had been pending then, when the novelty clause warned it (NaN when it did not), the
     * fold's miss rate, and its outcome.
     */
    public record HeldOut(int fold, boolean missed, double duration, List<Double> probabilities, List<Double> elapsed,
                   double caughtAt, double baseRate) {

        double peak() {
            return probabilities.stream().mapToDouble(p -> p).max().orElse(0);
        }
    }

    /**
     * Every held-out obligation of property {@code id} with a known outcome (met or missed), as the replay of its log
     * with its fold's models forecast it.
     */
    public static List<HeldOut> heldOut(String id, HeldOutFolds heldOut) {
        List<HeldOut> judged = new ArrayList<>();
        for (HeldOutFolds.Fold fold : heldOut.judged()) {
            Survival survival = fold.obligations().get(id);
            if (survival == null || survival.size() == 0) {
                continue; // watch gives no forecast without a training obligation: nothing to judge
            }
            for (HeldOutRun run : fold.runs()) {
                for (ReplayedRun.Obligation o : run.obligations()) {
                    if (o.property().id().equals(id) && (o.discharged() || o.missed())) {
                        judged.add(forecast(fold.index(), o, survival));
                    }
                }
            }
        }
        return judged;
    }

    /**
     * {@code o} as the replay forecast it: the forecasts that had evidence, and where the novelty clause warned it (the
     * replay's rule warns by that clause alone, {@link DeadlineRule#NOVELTY_ONLY}).
     */
    private static HeldOut forecast(int fold, ReplayedRun.Obligation o, Survival survival) {
        List<Double> ps = new ArrayList<>();
        List<Double> elapsed = new ArrayList<>();
        for (ReplayedRun.Step step : o.forecasts()) {
            if (!step.estimate().novel()) {
                ps.add(step.estimate().probability());
                elapsed.add(step.elapsed());
            }
        }
        return new HeldOut(fold, o.missed(), o.duration(), ps, elapsed, o.warnedAt(),
                survival.missRate(o.property().within().amount()));
    }
}
