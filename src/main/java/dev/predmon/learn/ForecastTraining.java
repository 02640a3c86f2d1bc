package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.BoundModel;
import dev.predmon.forecast.BoundRuns;
import dev.predmon.forecast.Calibration;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.Scorecard;
import dev.predmon.forecast.ScorecardTally;
import dev.predmon.forecast.StatsLearner;
import dev.predmon.forecast.ThresholdChoice;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.WarningRule;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.transducer.CompactMealy;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Predicate;

/**
 * Learns the forecast that goes with the machines: the per-state statistics over every training run
 * ({@link StatsLearner}), and the warning threshold chosen by cross-validation over the same runs ({@link Folds}):
 * each fold's machines and statistics are learned without it, its logs are replayed through {@code watch}'s own monitor
 * with them ({@link HeldOutRun#replay}), and each run's highest forecast before its violation decides
 * ({@link ThresholdChoice}).
 *
 * <p>The forecast rule also warns where the thesis's rule would, when every nominal machine was contradicted (every
 * nominal machine eliminated by an output it predicted otherwise while a faulty one matches, {@code confirm} pairs
 * on), and where the run is beyond the training runs that held with its value below theirs ({@link
 * ForecastModel#warns}). A held-out run so warned before its violation counts as reaching any threshold, so the
 * threshold is chosen for the runs those clauses do not catch.
 */
public final class ForecastTraining {

    /** Folds of the threshold's cross-validation (fewer with fewer logs). */
    static final int FOLDS = 5;

    private ForecastTraining() {
    }

    /**
     * The forecast of {@code machines} (by id), learned from the runs of {@code specs} in {@code traces}, with the
     * property's {@link Scorecard} from the same cross-validation. Each fold's held-out logs are replayed through
     * {@code watch}'s own monitor ({@link HeldOutRun#replay}) with the models learned without them.
     *
     * @param abstraction the abstraction the traces were read with (tuned to the noise): its safety property is the
     *                    forecast's
     * @param confirm     the pairs a faulty machine must match after the last nominal one is eliminated
     */
    public static ForecastModel train(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
                                      Map<String, CompactMealy<String, String>> machines, Alphabet<String> alphabet,
                                      Abstraction abstraction, int confirm) throws BadInputException {
        double limit = limit(abstraction);
        String property = property(abstraction);
        List<LogTrace.Run> runs = runsOf(specs, traces, log -> true);
        String unit = runs.isEmpty() ? "s" : runs.get(0).timing().unit();
        ForecastModel stats = StatsLearner.learn(machines, runs, unit, limit);
        List<Bound> others = others(abstraction);
        Map<String, String> sides = new TreeMap<>();
        Map<String, BoundModel> boundStats = new TreeMap<>();
        for (Bound b : others) {
            String side = BoundRuns.side(b, runs);
            sides.put(b.id(), side);
            boundStats.put(b.id(), new BoundModel(side, StatsLearner.learn(machines, BoundRuns.view(b, side, runs),
                    unit, BoundModel.limit(b, side))));
        }
        List<ScenarioSpec> read = present(specs, traces);
        Map<Path, Integer> folds = folds(read);
        if (folds.isEmpty()) {
            String note = "default " + ThresholdChoice.DEFAULT + ": too few logs to cross-validate";
            Map<String, BoundModel> bounds = new TreeMap<>();
            boundStats.forEach((id, b) -> bounds.put(id, new BoundModel(b.side(),
                    b.model().withThreshold(ThresholdChoice.DEFAULT, note, false))));
            return stats.withThreshold(ThresholdChoice.DEFAULT, note, false).withBounds(bounds);
        }
        int used = Folds.used(folds);
        List<HeldOut> judged = new ArrayList<>();
        Map<String, List<HeldOut>> boundJudged = new TreeMap<>();
        others.forEach(b -> boundJudged.put(b.id(), new ArrayList<>()));
        for (int f = 0; f < used; f++) {
            int fold = f;
            Predicate<Path> held = log -> folds.get(log) == fold;
            List<LearnedScenario> foldLearned = new ArrayList<>();
            for (ScenarioSpec s : read) {
                List<MealyTrace> samples = s.logs().stream().filter(held.negate())
                        .flatMap(l -> traces.get(l).samples(s.runs()).stream()).toList();
                if (!samples.isEmpty()) {
                    foldLearned.add(ScenarioLearner.learnSamples(s, samples, alphabet));
                }
            }
            List<LogTrace.Run> training = runsOf(read, traces, held.negate());
            // a fold that trains on one outcome only says nothing about where to draw the line
            boolean judges = !oneOutcome(training);
            Map<String, CompactMealy<String, String>> foldMachines = LearnedModels.machines(foldLearned);
            Map<String, BoundModel> foldBounds = new TreeMap<>();
            Map<String, Double> foldBaseRates = new TreeMap<>();
            for (Bound b : others) {
                List<LogTrace.Run> view = BoundRuns.view(b, sides.get(b.id()), training);
                if (!oneOutcome(view)) {
                    ForecastModel m = StatsLearner.learn(foldMachines, view, unit,
                            BoundModel.limit(b, sides.get(b.id())));
                    foldBounds.put(b.id(), new BoundModel(sides.get(b.id()),
                            m.withThreshold(HeldOutRun.NEVER, "held out", true)));
                    foldBaseRates.put(b.id(), m.baseRate());
                }
            }
            if (!judges && foldBounds.isEmpty()) {
                continue;
            }
            ForecastModel foldStats = StatsLearner.learn(foldMachines, training, unit, limit);
            // Warning at no probability, the rule's other clauses alone warn: those runs count as caught.
            ModelSet foldModels = LearnedModels.modelSet(foldLearned, abstraction,
                    foldStats.withThreshold(HeldOutRun.NEVER, "held out", true).withBounds(foldBounds));
            for (ScenarioSpec s : read) {
                for (Path log : s.logs()) {
                    if (!held.test(log)) {
                        continue;
                    }
                    try {
                        HeldOutRun.Judged replayed = HeldOutRun.replayAll(log, s.runs(), foldModels, abstraction,
                                confirm, WarningRule.FORECAST);
                        if (judges) {
                            for (HeldOutRun r : replayed.safety()) {
                                judged.add(new HeldOut(fold, r, foldStats.baseRate()));
                            }
                        }
                        replayed.bounds().forEach((id, rs) -> rs.forEach(r -> boundJudged.get(id)
                                .add(new HeldOut(fold, r, foldBaseRates.get(id)))));
                    } catch (IOException e) {
                        throw BadInputException.cannotRead(log, e);
                    }
                }
            }
        }
        Map<String, BoundModel> bounds = new TreeMap<>();
        for (Bound b : others) {
            BoundModel m = boundStats.get(b.id());
            bounds.put(b.id(), new BoundModel(m.side(), chosen(m.model(), b.name(), used, unit,
                    boundJudged.get(b.id()))));
        }
        return chosen(stats, property, used, unit, judged).withBounds(bounds);
    }

    /**
     * {@code stats} with the calibration, the threshold and the scorecard of {@code property} chosen on the held-out
     * runs {@code judged}.
     */
    private static ForecastModel chosen(ForecastModel stats, String property, int used, String unit,
                                        List<HeldOut> judged) {
        // The threshold is chosen on the calibrated scale, where even odds mean what they say.
        Calibration calibration = Calibration.fit(judged.stream().map(h -> new Calibration.Sample(
                h.run().probabilities(), h.run().violated())).toList());
        ThresholdChoice.Choice c = ThresholdChoice.choose(judged.stream().map(h -> new ThresholdChoice.Peak(
                calibration.apply(h.run().peak()), h.run().violated(), !Double.isNaN(h.run().warnedAt()))).toList());
        List<Scorecard> cards = scorecards(property, used, unit, judged);
        if (!c.validated()) {
            return stats.withThreshold(c.threshold(), c.note(), false).withScorecards(cards);
        }
        double threshold = c.threshold();
        String note = String.format(Locale.ROOT, "%.2f %s", threshold, c.note());
        return stats.withCalibration(calibration).withThreshold(threshold, note, true).withScorecards(cards);
    }

    private static boolean oneOutcome(List<LogTrace.Run> runs) {
        return runs.stream().allMatch(LogTrace.Run::violated) || runs.stream().noneMatch(LogTrace.Run::violated);
    }

    /**
     * Every bound property of {@code abstraction} but its safety property, with a floor or a ceiling: each gets a value
     * forecast of its own ({@link BoundModel}).
     */
    public static List<Bound> others(Abstraction abstraction) {
        String safety = abstraction.safety().map(Bound::id).orElse(null);
        List<Bound> out = new ArrayList<>();
        for (Property p : abstraction.properties()) {
            if (p instanceof Bound b && !b.id().equals(safety)
                    && (b.hasFloor() || b.ceiling() != Double.POSITIVE_INFINITY)) {
                out.add(b);
            }
        }
        return out;
    }

    /** One held-out run ({@link HeldOutRun}) with its fold and that fold's base rate. */
    private record HeldOut(int fold, HeldOutRun run, double baseRate) {
    }

    /**
     * The scorecard of {@code property} over the held-out runs, each judged as {@code watch} would, with a calibration
     * and a threshold chosen as above from the other folds' runs only: no figure rests on a choice that saw the run it
     * judges. None without a property or a judged run.
     */
    private static List<Scorecard> scorecards(String property, int folds, String unit, List<HeldOut> judged) {
        if (property == null || judged.isEmpty()) {
            return List.of();
        }
        ScorecardTally tally = new ScorecardTally();
        for (int f = 0; f < folds; f++) {
            int fold = f;
            List<HeldOut> others = judged.stream().filter(h -> h.fold() != fold).toList();
            Calibration calibration = Calibration.fit(others.stream()
                    .map(h -> new Calibration.Sample(h.run().probabilities(), h.run().violated())).toList());
            double threshold = ThresholdChoice.choose(others.stream().map(h -> new ThresholdChoice.Peak(
                    calibration.apply(h.run().peak()), h.run().violated(), !Double.isNaN(h.run().warnedAt())))
                    .toList()).threshold();
            for (HeldOut judgedRun : judged) {
                if (judgedRun.fold() == fold) {
                    HeldOutRun h = judgedRun.run();
                    tally.add(h.probabilities(), h.times(), h.warnedAt(), h.violated(), h.violationTime(),
                            judgedRun.baseRate(), calibration, threshold);
                }
            }
        }
        return List.of(tally.scorecard(property, folds, judged.size(), unit, Scorecard.RUNS));
    }

    /** The safety property's threshold, NaN when the abstraction has no property. */
    public static double limit(Abstraction abstraction) {
        return abstraction.safety().map(Bound::floor).orElse(Double.NaN);
    }

    /** The safety property's name, null when the abstraction has no property. */
    public static String property(Abstraction abstraction) {
        return abstraction.safety().map(Bound::name).orElse(null);
    }

    /** {@code specs} with only the logs {@code traces} holds (those that could be read). */
    static List<ScenarioSpec> present(List<ScenarioSpec> specs, Map<Path, LogTrace> traces) {
        return specs.stream().map(s -> s.withLogs(s.logs().stream().filter(traces::containsKey).toList())).toList();
    }

    /**
     * The fold of every log of {@code specs} in the cross-validation of the forecast's threshold and of every
     * deadline's ({@link Folds#assign}, at most {@value #FOLDS} folds); empty with fewer than two logs.
     */
    static Map<Path, Integer> folds(List<ScenarioSpec> specs) {
        long logs = specs.stream().flatMap(s -> s.logs().stream()).distinct().count();
        int k = (int) Math.min(FOLDS, logs);
        return k < 2 ? Map.of() : Folds.assign(specs, k);
    }

    /** The runs of the logs {@code include} selects, each of the runs its scenario learns from. */
    static List<LogTrace.Run> runsOf(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
                                     Predicate<Path> include) {
        List<LogTrace.Run> runs = new ArrayList<>();
        for (ScenarioSpec s : specs) {
            for (Path log : s.logs()) {
                LogTrace t = traces.get(log);
                if (t != null && include.test(log)) {
                    t.runs().stream().filter(r -> !r.pairs().isEmpty() && s.runs().selects(r.violated()))
                            .forEach(runs::add);
                }
            }
        }
        return runs;
    }
}
