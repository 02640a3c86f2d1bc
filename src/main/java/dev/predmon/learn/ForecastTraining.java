package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.BoundModel;
import dev.predmon.forecast.BoundRuns;
import dev.predmon.forecast.Clauses;
import dev.predmon.forecast.CrossValidation;
import dev.predmon.forecast.EventModel;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.PropertyParts;
import dev.predmon.forecast.Scorecard;
import dev.predmon.forecast.StatsLearner;
import dev.predmon.forecast.ThresholdChoice;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.property.Bound;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.transducer.CompactMealy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Predicate;

/**
 * Learns the forecast that goes with the machines: the per-state statistics over every training run
 * ({@link StatsLearner}), and the warning threshold chosen by cross-validation over the same runs ({@link Folds}):
 * each fold's machines and statistics are learned without it, its logs are replayed through {@code watch}'s own monitor
 * with them ({@link HeldOutFolds}, the replays the deadlines are chosen on too), and each run's highest forecast before
 * its violation decides ({@link ThresholdChoice}).
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
     * {@code watch}'s own monitor ({@link HeldOutFolds}) with the models learned without them; every other bound
     * property gets its forecast ({@link BoundModel}) from the same replays.
     *
     * @param abstraction the abstraction the traces were read with (tuned to the noise): its safety property is the
     *                    forecast's
     * @param confirm     the pairs a faulty machine must match after the last nominal one is eliminated
     */
    public static ForecastModel train(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
                                      Map<String, CompactMealy<String, String>> machines, Alphabet<String> alphabet,
                                      Abstraction abstraction, int confirm) throws BadInputException {
        return train(specs, traces, machines, abstraction, heldOut(specs, traces, alphabet, abstraction, confirm));
    }

    /**
     * The cross-validation's replays of the logs of {@code specs} ({@link HeldOutFolds#replay}), with the unit and
     * the property's threshold of {@link #train}: what it and {@link DeadlineTraining#train} choose on.
     */
    public static HeldOutFolds heldOut(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
                                       Alphabet<String> alphabet, Abstraction abstraction, int confirm)
            throws BadInputException {
        List<LogTrace.Run> runs = runsOf(specs, traces, log -> true);
        return HeldOutFolds.replay(specs, traces, alphabet, abstraction, unit(runs), limit(abstraction),
                sides(others(abstraction), runs), confirm);
    }

    /**
     * As above, choosing on {@code heldOut}, the replays {@link #heldOut} made of the same logs.
     */
    public static ForecastModel train(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
                                      Map<String, CompactMealy<String, String>> machines, Abstraction abstraction,
                                      HeldOutFolds heldOut) {
        double limit = limit(abstraction);
        String property = property(abstraction);
        List<LogTrace.Run> runs = runsOf(specs, traces, log -> true);
        String unit = unit(runs);
        ForecastModel stats = StatsLearner.learn(machines, runs, unit, limit);
        List<Bound> others = others(abstraction);
        Map<String, String> sides = sides(others, runs);
        Map<String, BoundModel> boundStats = new TreeMap<>();
        for (Bound b : others) {
            String side = sides.get(b.id());
            boundStats.put(b.id(), new BoundModel(side, StatsLearner.learn(machines, BoundRuns.view(b, side, runs),
                    unit, BoundModel.limit(b, side))));
        }
        Map<String, EventModel> events = EventTraining.train(machines, abstraction, runs, unit, heldOut);
        if (heldOut.folds() == 0) {
            String note = "default " + ThresholdChoice.DEFAULT + ": too few logs to cross-validate";
            Map<String, BoundModel> bounds = new TreeMap<>();
            boundStats.forEach((id, b) -> bounds.put(id, new BoundModel(b.side(),
                    b.model().withThreshold(ThresholdChoice.DEFAULT, note, false))));
            return PropertyParts.covering(stats.withThreshold(ThresholdChoice.DEFAULT, note, false)
                    .withBounds(bounds).withEvents(events), abstraction);
        }
        String first = abstraction.safety().map(Bound::id).orElse(null);
        Map<String, List<CrossValidation.Case>> judged = new HashMap<>(); // by bound id, the first floor's too
        judged.put(first, new ArrayList<>());
        others.forEach(b -> judged.put(b.id(), new ArrayList<>()));
        for (HeldOutFolds.Fold fold : heldOut.judged()) {
            fold.values(first).forEach((id, b) -> {
                boolean ceiling = BoundModel.CEILING.equals(sides.get(id));
                b.runs().forEach(r -> judged.get(id).add(HeldOutCases.bound(fold.index(), r, b.baseRate(),
                        b.safeFloor(), v -> ceiling ? -v : v)));
            });
        }
        Map<String, BoundModel> bounds = new TreeMap<>();
        for (Bound b : others) {
            BoundModel m = boundStats.get(b.id());
            bounds.put(b.id(), new BoundModel(m.side(), chosen(m.model(), b.name(), heldOut.folds(), unit,
                    judged.get(b.id()), new CrossValidation.Space(1, 0, Scorecard.RUNS))));
        }
        return PropertyParts.covering(chosen(stats, property, heldOut.folds(), unit, judged.get(first),
                new CrossValidation.Space(1, 1, Scorecard.RUNS)).withBounds(bounds).withEvents(events), abstraction);
    }

    /**
     * {@code stats} with the rule of {@code property} chosen on the held-out runs {@code judged} by the one
     * cross-validation ({@link CrossValidation}): its calibration, threshold and clauses (the novelty clause, and the
     * thesis's matching where {@code space} offers it and it earns its place), or the raw-value baseline where the
     * learned rule did worse on the same folds; and its scorecard beside the baseline's.
     */
    private static ForecastModel chosen(ForecastModel stats, String property, int used, String unit,
                                        List<CrossValidation.Case> judged, CrossValidation.Space space) {
        CrossValidation.Choice c = CrossValidation.choose(judged, used, space, new Scorecard.Names(property, unit,
                Scorecard.RUNS, Scorecard.FORECAST, Scorecard.RAW_VALUE));
        CrossValidation.Rule r = c.rule();
        List<Scorecard> cards = property == null || c.scorecard() == null ? List.of() : List.of(c.scorecard());
        Clauses clauses = c.baseline() ? Clauses.BASELINE : new Clauses(false, r.keeps(0));
        String note = c.baseline() ? r.note() + "; " + BASELINE_NOTE : r.note();
        ForecastModel m = stats.withThreshold(r.threshold(), note, r.validated()).withScorecards(cards)
                .withClauses(clauses);
        return r.validated() ? m.withCalibration(r.calibration()) : m;
    }

    /** Why a model warns by the raw-value baseline, after its threshold's note. */
    static final String BASELINE_NOTE = "the raw-value baseline warns: the forecast's rule did worse on the same folds";

    /**
     * Every bound property of {@code abstraction} but its safety property, with a floor or a ceiling: each gets a value
     * forecast of its own ({@link BoundModel}).
     */
    public static List<Bound> others(Abstraction abstraction) {
        return PropertyParts.others(abstraction);
    }

    /** By id, the side of each of {@code others} its forecast predicts, as {@code runs} cross it. */
    static Map<String, String> sides(List<Bound> others, List<LogTrace.Run> runs) {
        Map<String, String> sides = new TreeMap<>();
        others.forEach(b -> sides.put(b.id(), BoundRuns.side(b, runs)));
        return sides;
    }

    /** What the runs' times count: the first run's unit, seconds without a run. */
    private static String unit(List<LogTrace.Run> runs) {
        return runs.isEmpty() ? "s" : runs.get(0).timing().unit();
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
