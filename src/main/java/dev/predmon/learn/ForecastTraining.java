package dev.predmon.learn;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.SafetyRule;
import dev.predmon.forecast.Calibration;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.Forecaster;
import dev.predmon.forecast.StatsLearner;
import dev.predmon.forecast.ThresholdChoice;
import dev.predmon.matching.Matching;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.LearnedModel;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.transducer.CompactMealy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Predicate;

/**
 * Learns the forecast that goes with the machines: the per-state statistics over every training run
 * ({@link StatsLearner}), and the warning threshold chosen by cross-validation over the same runs: each fold's
 * machines and statistics are learned without it, its runs are forecast pair by pair, and each run's highest
 * forecast before its violation decides ({@link ThresholdChoice}).
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
     * The forecast of {@code machines} (by id), learned from the runs of {@code specs} in {@code traces}.
     *
     * @param limit   the safety property's threshold, NaN without a property
     * @param confirm the pairs a faulty machine must match after the last nominal one is eliminated
     */
    public static ForecastModel train(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
                                      Map<String, CompactMealy<String, String>> machines, Alphabet<String> alphabet,
                                      double limit, int confirm) {
        List<LogTrace.Run> runs = runsOf(specs, traces, log -> true);
        String unit = runs.isEmpty() ? "s" : runs.get(0).timing().unit();
        ForecastModel stats = StatsLearner.learn(machines, runs, unit, limit);
        List<Path> logs = specs.stream().flatMap(s -> s.logs().stream()).filter(traces::containsKey).distinct()
                .sorted().toList();
        int k = Math.min(FOLDS, logs.size());
        if (k < 2) {
            return stats.withThreshold(ThresholdChoice.DEFAULT, "default " + ThresholdChoice.DEFAULT
                    + ": too few logs to cross-validate", false);
        }
        List<ThresholdChoice.Peak> peaks = new ArrayList<>();
        List<Calibration.Sample> heldOut = new ArrayList<>();
        for (int f = 0; f < k; f++) {
            int fold = f;
            List<Path> held = new ArrayList<>();
            for (int i = fold; i < logs.size(); i += k) {
                held.add(logs.get(i));
            }
            List<LearnedScenario> foldLearned = new ArrayList<>();
            for (ScenarioSpec s : specs) {
                List<MealyTrace> samples = s.logs().stream().filter(traces::containsKey).filter(l -> !held.contains(l))
                        .flatMap(l -> traces.get(l).samples(s.runs()).stream()).toList();
                if (!samples.isEmpty()) {
                    foldLearned.add(ScenarioLearner.learnSamples(s, samples, alphabet));
                }
            }
            Map<String, CompactMealy<String, String>> foldMachines = LearnedModels.machines(foldLearned);
            List<LearnedModel> foldModels = LearnedModels.models(foldLearned, alphabet);
            List<LogTrace.Run> training = runsOf(specs, traces, l -> !held.contains(l));
            if (training.stream().allMatch(LogTrace.Run::violated) || training.stream().noneMatch(LogTrace.Run::violated)) {
                continue; // a fold that trains on one outcome only says nothing about where to draw the line
            }
            ForecastModel foldStats = StatsLearner.learn(foldMachines, training, unit, limit);
            Forecaster forecaster = new Forecaster(foldStats, foldMachines);
            for (LogTrace.Run r : runsOf(specs, traces, held::contains)) {
                List<Double> ps = forecast(forecaster, r).stream().map(Forecast::probability).toList();
                peaks.add(new ThresholdChoice.Peak(ps.stream().mapToDouble(p -> p).max().orElse(0), r.violated(),
                        warnsAnyway(foldModels, foldStats, confirm, r)));
                heldOut.add(new Calibration.Sample(ps, r.violated()));
            }
        }
        // The threshold is chosen on the calibrated scale, where even odds mean what they say.
        Calibration calibration = Calibration.fit(heldOut);
        ThresholdChoice.Choice c = ThresholdChoice.choose(peaks.stream().map(p -> new ThresholdChoice.Peak(
                calibration.apply(p.probability()), p.violated(), p.caught())).toList());
        if (!c.validated()) {
            return stats.withThreshold(c.threshold(), c.note(), false);
        }
        double threshold = c.threshold();
        String note = String.format(Locale.ROOT, "%.2f %s", threshold, c.note());
        return stats.withCalibration(calibration).withThreshold(threshold, note, true);
    }

    /** The safety property's threshold, NaN when the abstraction has no property. */
    public static double limit(Abstraction abstraction) {
        return abstraction.safety().map(SafetyRule::below).orElse(Double.NaN);
    }

    /**
     * Whether the forecast rule warns {@code run} before its violation whatever its threshold, as watch takes the
     * rule's other clauses ({@link ForecastModel#warns}): the thesis's rule ({@link Matching}, each machine matched
     * exactly) when every nominal machine was contradicted and the run has no gap yet ({@link RunTiming#gaps}), or
     * the value below the lowest of the training runs that held once the run is beyond them (a gap, or no nominal
     * machine matching).
     */
    static boolean warnsAnyway(List<LearnedModel> models, ForecastModel stats, int confirm, LogTrace.Run run) {
        Matching matching = new Matching(models, 0, confirm);
        RunTiming t = run.timing();
        List<RunTiming.Gap> gaps = t.gaps();
        List<RunTiming.Reading> readings = t.readings();
        int r = 0;
        for (int i = 0; ; i++) {
            boolean gap = !gaps.isEmpty() && gaps.get(0).pairsBefore() <= i;
            boolean beyond = gap || !matching.nominalAlive();
            for (; r < readings.size() && readings.get(r).pairsBefore() <= i; r++) {
                RunTiming.Reading x = readings.get(r);
                if (beyond && stats.belowSafeFloor(x.value()) && beforeViolation(run, x.time())) {
                    return true; // as watch does at a new reading
                }
            }
            if (i == run.pairs().size() || !beforeViolation(run, t.time(i))) {
                return false;
            }
            Matching.Step step = matching.pair(run.pairs().get(i));
            if (step.ruleWarns() && step.contradicted() && !gap) {
                return true;
            }
            if ((gap || !step.nominalAlive()) && stats.belowSafeFloor(t.value(i))) {
                return true;
            }
        }
    }

    /** Whether {@code time} is before {@code run}'s violation (always, for a run that held). */
    private static boolean beforeViolation(LogTrace.Run run, double time) {
        return !run.violated() || time < run.timing().violationTime();
    }

    /**
     * The forecasts of {@code run} before its violation, in the order {@code watch} makes them: after each new value
     * of the property and after each pair.
     */
    public static List<Forecast> forecast(Forecaster forecaster, LogTrace.Run run) {
        forecaster.reset();
        List<Forecast> out = new ArrayList<>();
        RunTiming t = run.timing();
        List<RunTiming.Reading> readings = t.readings();
        List<RunTiming.Gap> gaps = t.gaps();
        int r = 0;
        int g = 0;
        for (int i = 0; i <= run.pairs().size(); i++) {
            for (; g < gaps.size() && gaps.get(g).pairsBefore() <= i; g++) {
                forecaster.unseen(gaps.get(g).line()); // as watch does at a message the models cannot read
            }
            for (; r < readings.size() && readings.get(r).pairsBefore() <= i; r++) {
                RunTiming.Reading x = readings.get(r);
                if (!beforeViolation(run, x.time())) {
                    return out;
                }
                out.add(forecaster.reading(x.time(), x.value()));
            }
            if (i == run.pairs().size()) {
                break;
            }
            if (!beforeViolation(run, t.time(i))) {
                break;
            }
            out.add(forecaster.pair(run.pairs().get(i).input(), run.pairs().get(i).output(), t.time(i), t.value(i),
                    i));
        }
        return out;
    }

    /** The runs of the logs {@code include} selects, each of the runs its scenario learns from. */
    private static List<LogTrace.Run> runsOf(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
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
