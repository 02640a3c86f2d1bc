package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.StatsLearner;
import dev.predmon.forecast.Survival;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.WarningRule;
import dev.predmon.pipeline.LogTrace;
import net.automatalib.alphabet.Alphabet;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Predicate;

/**
 * The cross-validation's held-out replays, made once for every training that chooses on them: for each fold
 * ({@link ForecastTraining#folds}), the scenarios' machines and the forecast statistics learned without its logs, and
 * its logs replayed through {@code watch}'s own monitor with them ({@link HeldOutRun#replay}), one replay per held-out
 * log. The forecast's threshold ({@link ForecastTraining}) and every deadline's ({@link DeadlineTraining}) are chosen
 * on the same replays, so on the forecasts {@code watch} makes.
 *
 * <p>The replayed models warn by the rules' other clauses alone (the forecast's threshold is {@link
 * HeldOutRun#NEVER}, every deadline's {@link DeadlineRule#NOVELTY_ONLY}): what those clauses catch is caught whatever
 * threshold is chosen after.
 *
 * @param folds the folds used (0 with fewer than two logs: nothing to cross-validate)
 * @param judged every fold that was replayed, in fold order; a fold whose training runs have neither both outcomes
 *               nor an obligation says nothing and is left out
 */
public record HeldOutFolds(int folds, List<Fold> judged) {

    public HeldOutFolds {
        judged = List.copyOf(judged);
    }

    /**
     * One fold, replayed.
     *
     * @param index         the fold
     * @param baseRate      the base rate of its training runs (the other folds'), as its models forecast it
     * @param obligations   by bounded-response property id, the durations of its training runs' obligations: its
     *                      models' deadline forecast ({@link ForecastModel#obligations})
     * @param bothOutcomes  whether its training runs both violated the forecast's property and held it: only then does
     *                      it say where to draw the forecast's line
     * @param runs          its held-out runs, each of the runs its scenario learns from, in log order
     */
    public record Fold(int index, double baseRate, Map<String, Survival> obligations, boolean bothOutcomes,
                       List<HeldOutRun> runs) {

        public Fold {
            obligations = Map.copyOf(obligations);
            runs = List.copyOf(runs);
        }
    }

    /**
     * Every fold of the logs of {@code specs} in {@code traces} replayed with the machines and statistics learned
     * without it.
     *
     * @param abstraction the abstraction the traces were read with (tuned to the noise)
     * @param unit        what the runs' times count
     * @param limit       the forecast property's threshold, NaN without one
     * @param confirm     the pairs a faulty machine must match after the last nominal one is eliminated
     */
    public static HeldOutFolds replay(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
                                      Alphabet<String> alphabet, Abstraction abstraction, String unit, double limit,
                                      int confirm) throws BadInputException {
        List<ScenarioSpec> read = ForecastTraining.present(specs, traces);
        Map<Path, Integer> folds = ForecastTraining.folds(read);
        if (folds.isEmpty()) {
            return new HeldOutFolds(0, List.of());
        }
        int used = Folds.used(folds);
        List<Fold> judged = new ArrayList<>();
        for (int f = 0; f < used; f++) {
            int fold = f;
            Predicate<Path> held = log -> folds.get(log) == fold;
            List<LogTrace.Run> training = ForecastTraining.runsOf(read, traces, held.negate());
            boolean both = training.stream().anyMatch(LogTrace.Run::violated)
                    && !training.stream().allMatch(LogTrace.Run::violated);
            if (!both && StatsLearner.obligations(training).isEmpty()) {
                continue; // nothing to draw a line with, for the forecast or for a deadline
            }
            List<LearnedScenario> foldLearned = new ArrayList<>();
            for (ScenarioSpec s : read) {
                List<MealyTrace> samples = s.logs().stream().filter(held.negate())
                        .flatMap(l -> traces.get(l).samples(s.runs()).stream()).toList();
                if (!samples.isEmpty()) {
                    foldLearned.add(ScenarioLearner.learnSamples(s, samples, alphabet));
                }
            }
            ForecastModel stats = StatsLearner.learn(LearnedModels.machines(foldLearned), training, unit, limit);
            Map<String, DeadlineRule> noveltyOnly = new TreeMap<>();
            stats.obligations().keySet().forEach(id -> noveltyOnly.put(id, DeadlineRule.NOVELTY_ONLY));
            ModelSet models = LearnedModels.modelSet(foldLearned, abstraction,
                    stats.withThreshold(HeldOutRun.NEVER, "held out", true).withDeadlines(noveltyOnly));
            List<HeldOutRun> runs = new ArrayList<>();
            for (ScenarioSpec s : read) {
                for (Path log : s.logs()) {
                    if (!held.test(log)) {
                        continue;
                    }
                    try {
                        runs.addAll(HeldOutRun.replay(log, s.runs(), models, abstraction, confirm,
                                WarningRule.FORECAST));
                    } catch (IOException e) {
                        throw BadInputException.cannotRead(log, e);
                    }
                }
            }
            judged.add(new Fold(fold, stats.baseRate(), stats.obligations(), both, runs));
        }
        return new HeldOutFolds(used, judged);
    }
}
