package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.BoundModel;
import dev.predmon.forecast.BoundRuns;
import dev.predmon.forecast.DeadlineRule;
import dev.predmon.forecast.EventModel;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.StatsLearner;
import dev.predmon.forecast.Survival;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.WarningRule;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.property.Bound;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.transducer.CompactMealy;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Predicate;

/**
 * The cross-validation's held-out replays, made once for every training that chooses on them: for each fold
 * ({@link ForecastTraining#folds}), the scenarios' machines and the forecast statistics learned without its logs, and
 * its logs replayed through {@code watch}'s own monitor with them ({@link HeldOutRun#replayAll}), one replay per
 * held-out log. The forecast's threshold ({@link ForecastTraining}), every other bound property's ({@link BoundModel})
 * and every deadline's ({@link DeadlineTraining}) are chosen on the same replays, so on the forecasts {@code watch}
 * makes.
 *
 * <p>The replayed models warn by the rules' other clauses alone (the forecast's threshold and every bound property's
 * are {@link HeldOutRun#NEVER}, every deadline's {@link DeadlineRule#NOVELTY_ONLY}): what those clauses catch is caught
 * whatever threshold is chosen after.
 *
 * @param folds the folds used (0 with fewer than two logs: nothing to cross-validate)
 * @param judged every fold that was replayed, in fold order; a fold whose training runs have neither both outcomes
 *               (of the forecast's property or of another bound property) nor an obligation says nothing and is left
 *               out
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
     * @param bounds        by id, every other bound property whose training runs (as it sees them, {@link BoundRuns})
     *                      both violated and held it: the same held-out runs as it saw them in the same replays
     * @param safeFloor     the lowest value a training run that held the forecast's property read (NaN without one):
     *                      the raw-value baseline's line
     * @param events        by id, every absence and precedence whose training runs could teach a forecast
     *                      ({@link EventTraining}): the same held-out runs as it saw them ({@code safeFloor} NaN)
     */
    public record Fold(int index, double baseRate, Map<String, Survival> obligations, boolean bothOutcomes,
                       List<HeldOutRun> runs, Map<String, BoundFold> bounds, double safeFloor,
                       Map<String, BoundFold> events) {

        public Fold {
            obligations = Map.copyOf(obligations);
            runs = List.copyOf(runs);
            bounds = Map.copyOf(bounds);
            events = Map.copyOf(events);
        }

        /**
         * Every bound's part of this fold by id: the first floor's ({@code firstFloor}: the runs, base rate and
         * raw-value line above, when its training runs had both outcomes) as any other bound's ({@link #bounds}).
         */
        public Map<String, BoundFold> values(String firstFloor) {
            Map<String, BoundFold> all = new HashMap<>(bounds);
            if (bothOutcomes) {
                all.put(firstFloor, new BoundFold(baseRate, runs, safeFloor));
            }
            return all;
        }

        /** A fold without absences' and precedences' forecasts. */
        public Fold(int index, double baseRate, Map<String, Survival> obligations, boolean bothOutcomes,
                    List<HeldOutRun> runs, Map<String, BoundFold> bounds, double safeFloor) {
            this(index, baseRate, obligations, bothOutcomes, runs, bounds, safeFloor, Map.of());
        }

        /** A fold with no bound property of its own forecast. */
        public Fold(int index, double baseRate, Map<String, Survival> obligations, boolean bothOutcomes,
                    List<HeldOutRun> runs) {
            this(index, baseRate, obligations, bothOutcomes, runs, Map.of(), Double.NaN);
        }
    }

    /**
     * One bound property in one fold.
     *
     * @param baseRate the base rate of the fold's training runs as the property sees them
     * @param runs     the fold's held-out runs as the property saw them: its own violation, forecasts and warning
     * @param safeFloor the lowest value, on the forecast's scale, a training run that held the property read (NaN
     *                  without one): the raw-value baseline's line
     */
    public record BoundFold(double baseRate, List<HeldOutRun> runs, double safeFloor) {

        public BoundFold {
            runs = List.copyOf(runs);
        }

        /** The fold of the bound forecast by {@code model} (on its scale), its held-out runs {@code runs}. */
        static BoundFold of(ForecastModel model, List<HeldOutRun> runs) {
            return new BoundFold(model.baseRate(), runs, model.lows().safeFloor());
        }
    }

    /**
     * Every fold of the logs of {@code specs} in {@code traces} replayed with the machines and statistics learned
     * without it.
     *
     * @param abstraction the abstraction the traces were read with (tuned to the noise)
     * @param unit        what the runs' times count
     * @param limit       the forecast property's threshold, NaN without one
     * @param sides       by id, the side of every other bound property its forecast predicts
     *                    ({@link ForecastTraining#others}, {@link BoundRuns#side})
     * @param confirm     the pairs a faulty machine must match after the last nominal one is eliminated
     */
    public static HeldOutFolds replay(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
                                      Alphabet<String> alphabet, Abstraction abstraction, String unit, double limit,
                                      Map<String, String> sides, int confirm) throws BadInputException {
        List<Bound> others = ForecastTraining.others(abstraction);
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
            boolean both = bothOutcomes(training);
            Map<String, List<LogTrace.Run>> views = new TreeMap<>();
            for (Bound b : others) {
                List<LogTrace.Run> view = BoundRuns.view(b, sides.get(b.id()), training);
                if (bothOutcomes(view)) {
                    views.put(b.id(), view);
                }
            }
            if (!both && views.isEmpty() && StatsLearner.obligations(training).isEmpty()
                    && !EventTraining.teaches(abstraction, training)) {
                continue; // nothing to draw a line with, for the forecast, a bound property or a deadline
            }
            List<LearnedScenario> foldLearned = new ArrayList<>();
            for (ScenarioSpec s : read) {
                List<MealyTrace> samples = s.logs().stream().filter(held.negate())
                        .flatMap(l -> traces.get(l).samples(s.runs()).stream()).toList();
                if (!samples.isEmpty()) {
                    foldLearned.add(ScenarioLearner.learnSamples(s, samples, alphabet));
                }
            }
            Map<String, CompactMealy<String, String>> machines = LearnedModels.machines(foldLearned);
            ForecastModel stats = StatsLearner.learn(machines, training, unit, limit);
            Map<String, DeadlineRule> noveltyOnly = new TreeMap<>();
            stats.obligations().keySet().forEach(id -> noveltyOnly.put(id, DeadlineRule.NOVELTY_ONLY));
            Map<String, BoundModel> boundModels = new TreeMap<>();
            for (Bound b : others) {
                List<LogTrace.Run> view = views.get(b.id());
                if (view != null) {
                    String side = sides.get(b.id());
                    boundModels.put(b.id(), new BoundModel(side, StatsLearner.learn(machines, view, unit,
                            BoundModel.limit(b, side)).withThreshold(HeldOutRun.NEVER, "held out", true)));
                }
            }
            Map<String, EventModel> eventModels = EventTraining.heldOut(machines, abstraction, training, unit);
            ModelSet models = LearnedModels.modelSet(foldLearned, abstraction, stats.withThreshold(HeldOutRun.NEVER,
                    "held out", true).withDeadlines(noveltyOnly).withBounds(boundModels).withEvents(eventModels));
            List<HeldOutRun> runs = new ArrayList<>();
            Map<String, List<HeldOutRun>> boundRuns = new TreeMap<>();
            boundModels.keySet().forEach(id -> boundRuns.put(id, new ArrayList<>()));
            Map<String, List<HeldOutRun>> eventRuns = new TreeMap<>();
            eventModels.keySet().forEach(id -> eventRuns.put(id, new ArrayList<>()));
            for (ScenarioSpec s : read) {
                for (Path log : s.logs()) {
                    if (!held.test(log)) {
                        continue;
                    }
                    try {
                        HeldOutRun.Judged replayed = HeldOutRun.replayAll(log, s.runs(), models, abstraction,
                                confirm, WarningRule.FORECAST);
                        runs.addAll(replayed.safety());
                        replayed.bounds().forEach((id, rs) -> (boundRuns.containsKey(id) ? boundRuns : eventRuns)
                                .get(id).addAll(rs));
                    } catch (IOException e) {
                        throw BadInputException.cannotRead(log, e);
                    }
                }
            }
            Map<String, BoundFold> bounds = new TreeMap<>();
            boundRuns.forEach((id, rs) -> bounds.put(id, BoundFold.of(boundModels.get(id).model(), rs)));
            Map<String, BoundFold> events = new TreeMap<>();
            eventRuns.forEach((id, rs) -> events.put(id, new BoundFold(eventModels.get(id).model().baseRate(), rs,
                    Double.NaN)));
            BoundFold first = BoundFold.of(stats, runs); // the first floor's, as every other bound's
            judged.add(new Fold(fold, first.baseRate(), stats.obligations(), both, first.runs(), bounds,
                    first.safeFloor(), events));
        }
        return new HeldOutFolds(used, judged);
    }

    /** Whether {@code runs} both violated their property and held it. */
    private static boolean bothOutcomes(List<LogTrace.Run> runs) {
        return runs.stream().anyMatch(LogTrace.Run::violated) && !runs.stream().allMatch(LogTrace.Run::violated);
    }
}
