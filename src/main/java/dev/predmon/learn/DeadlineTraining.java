package dev.predmon.learn;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.Calibration;
import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.Scorecard;
import dev.predmon.forecast.ScorecardTally;
import dev.predmon.forecast.Survival;
import dev.predmon.forecast.ThresholdChoice;
import dev.predmon.property.Deadline;
import dev.predmon.property.Property;
import dev.predmon.property.Response;
import dev.predmon.replay.ReplayedRun;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * Learns when the deadline forecast of each bounded-response property warns, by the cross-validation that chooses the
 * battery's threshold ({@link ForecastTraining}), on the same replays ({@link HeldOutFolds}): for each fold, the
 * durations of the other folds' obligations make the {@link Survival} estimate of the fold's models, and each held-out
 * obligation is forecast as {@code watch}'s own monitor forecast it in the replay of its log with them, one replay of
 * each held-out log for every property ({@link ReplayedRun#obligations}). Each obligation's
 * highest forecast before its deadline, and whether it missed, choose the threshold ({@link ThresholdChoice}); its
 * forecasts fit the {@link Calibration}; the novelty clause of {@link DeadlineRule} warns it whatever the threshold.
 *
 * <p>An obligation let go before its deadline (its run ended, or its scope closed) has no known outcome and is left
 * out. Where the held-out obligations cannot choose (too few logs, or none missed its deadline), the property keeps
 * {@link DeadlineRule#DEFAULT}, not validated, and the note says why.
 *
 * <p>The scorecard of each property comes from the same held-out forecasts, each fold judged with a threshold and a
 * calibration chosen from the other folds only. A property none of whose held-out obligations missed its deadline
 * gets none, as the forecast's property gets none without runs of both outcomes: there is no warning to score, and
 * its rule's note says it is not validated.
 */
public final class DeadlineTraining {

    private DeadlineTraining() {
    }

    /**
     * {@code model} with the deadline rule of every property it learned obligations for, chosen on {@code heldOut},
     * the cross-validation's replays of its training logs ({@link ForecastTraining#heldOut}), and their scorecards
     * after its own.
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
        List<Scorecard> cards = new ArrayList<>(model.scorecards());
        for (Response r : responses.values()) {
            if (k < 2) {
                rules.put(r.id(), new DeadlineRule(ThresholdChoice.DEFAULT, String.format(Locale.ROOT,
                        "default %.2f: too few logs to cross-validate", ThresholdChoice.DEFAULT), false,
                        Calibration.IDENTITY));
                continue;
            }
            List<HeldOut> judged = heldOut(r.id(), heldOut);
            rules.put(r.id(), rule(judged));
            if (judged.stream().anyMatch(HeldOut::missed)) {
                cards.add(scorecard(r, k, judged)); // without a missed deadline, nothing to score (the rule says so)
            }
        }
        return model.withDeadlines(rules).withScorecards(cards);
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

    /** The rule {@code judged} choose: a threshold and a calibration when they validate one, else the default. */
    static DeadlineRule rule(List<HeldOut> judged) {
        if (judged.isEmpty()) {
            return new DeadlineRule(ThresholdChoice.DEFAULT, String.format(Locale.ROOT, "default %.2f: no held-out "
                    + "obligation was met or missed", ThresholdChoice.DEFAULT), false, Calibration.IDENTITY);
        }
        Calibration calibration = fit(judged);
        ThresholdChoice.Choice c = choose(judged, calibration);
        if (!c.validated()) {
            return new DeadlineRule(c.threshold(), c.note() + "; not validated: even odds, and the warning past "
                    + "every training obligation", false, Calibration.IDENTITY);
        }
        return new DeadlineRule(c.threshold(), String.format(Locale.ROOT, "%.2f %s", c.threshold(), c.note()), true,
                calibration);
    }

    private static Calibration fit(List<HeldOut> judged) {
        return Calibration.fit(judged.stream().map(h -> new Calibration.Sample(h.probabilities(), h.missed()))
                .toList());
    }

    /** The threshold on the calibrated scale, where even odds mean what they say. */
    private static ThresholdChoice.Choice choose(List<HeldOut> judged, Calibration calibration) {
        return ThresholdChoice.choose(judged.stream().map(h -> new ThresholdChoice.Peak(
                calibration.apply(h.peak()), h.missed(), !Double.isNaN(h.caughtAt()))).toList(), "obligations");
    }

    /**
     * The scorecard of {@code property} over the held-out obligations, each fold judged as {@code watch} would with
     * the rule {@link #rule} makes from the other folds' obligations only. The lead runs from the warning to the
     * deadline's passing, in the deadline's unit.
     */
    static Scorecard scorecard(Response property, int folds, List<HeldOut> judged) {
        ScorecardTally tally = new ScorecardTally();
        for (int f = 0; f < folds; f++) {
            int fold = f;
            DeadlineRule rule = rule(judged.stream().filter(h -> h.fold() != fold).toList());
            judged.stream().filter(h -> h.fold() == fold).forEach(h -> tally.add(h.probabilities(), h.elapsed(),
                    h.caughtAt(), h.missed(), h.duration(), h.baseRate(), rule.calibration(), rule.threshold()));
        }
        Deadline d = property.within();
        return tally.scorecard(property.name(), folds, judged.size(),
                d.unit().key, Scorecard.OBLIGATIONS);
    }
}
