package dev.predmon.learn;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.Calibration;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.Forecaster;
import dev.predmon.forecast.Scorecard;
import dev.predmon.forecast.StatsLearner;
import dev.predmon.forecast.ThresholdChoice;
import dev.predmon.matching.Matching;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.LearnedModel;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import dev.predmon.property.Bound;
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
     * The forecast of {@code machines} (by id), learned from the runs of {@code specs} in {@code traces}, with the
     * property's {@link Scorecard} from the same cross-validation.
     *
     * @param limit    the safety property's threshold, NaN without a property
     * @param property the safety property's name, null without a property (then no scorecard)
     * @param confirm  the pairs a faulty machine must match after the last nominal one is eliminated
     */
    public static ForecastModel train(List<ScenarioSpec> specs, Map<Path, LogTrace> traces,
                                      Map<String, CompactMealy<String, String>> machines, Alphabet<String> alphabet,
                                      double limit, String property, int confirm) {
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
        List<HeldOut> judged = new ArrayList<>();
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
                List<Double> times = new ArrayList<>();
                List<Double> ps = forecast(forecaster, r, times).stream().map(Forecast::probability).toList();
                double caughtAt = warnsAnywayAt(foldModels, foldStats, confirm, r);
                peaks.add(new ThresholdChoice.Peak(ps.stream().mapToDouble(p -> p).max().orElse(0), r.violated(),
                        !Double.isNaN(caughtAt)));
                heldOut.add(new Calibration.Sample(ps, r.violated()));
                judged.add(new HeldOut(fold, r, ps, times, caughtAt, foldStats.baseRate()));
            }
        }
        // The threshold is chosen on the calibrated scale, where even odds mean what they say.
        Calibration calibration = Calibration.fit(heldOut);
        ThresholdChoice.Choice c = ThresholdChoice.choose(peaks.stream().map(p -> new ThresholdChoice.Peak(
                calibration.apply(p.probability()), p.violated(), p.caught())).toList());
        if (!c.validated()) {
            return stats.withThreshold(c.threshold(), c.note(), false)
                    .withScorecards(scorecards(property, k, unit, judged));
        }
        double threshold = c.threshold();
        String note = String.format(Locale.ROOT, "%.2f %s", threshold, c.note());
        return stats.withCalibration(calibration).withThreshold(threshold, note, true)
                .withScorecards(scorecards(property, k, unit, judged));
    }

    /**
     * One held-out run as its fold's models forecast it: the raw probabilities and the time of each, when the rule's
     * other clauses warned it (NaN when they did not), and the fold's base rate.
     */
    private record HeldOut(int fold, LogTrace.Run run, List<Double> probabilities, List<Double> times,
                           double caughtAt, double baseRate) {

        double peak() {
            return probabilities.stream().mapToDouble(p -> p).max().orElse(0);
        }
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
        int violating = 0;
        int warned = 0;
        int alarms = 0;
        List<Double> leads = new ArrayList<>();
        double brier = 0;
        double base = 0;
        int scored = 0;
        for (int f = 0; f < folds; f++) {
            int fold = f;
            List<HeldOut> others = judged.stream().filter(h -> h.fold() != fold).toList();
            Calibration calibration = Calibration.fit(others.stream()
                    .map(h -> new Calibration.Sample(h.probabilities(), h.run().violated())).toList());
            double threshold = ThresholdChoice.choose(others.stream().map(h -> new ThresholdChoice.Peak(
                    calibration.apply(h.peak()), h.run().violated(), !Double.isNaN(h.caughtAt())))
                    .toList()).threshold();
            for (HeldOut h : judged) {
                if (h.fold() != fold) {
                    continue;
                }
                boolean violated = h.run().violated();
                double y = violated ? 1 : 0;
                double warnedAt = h.caughtAt();
                double sum = 0;
                for (int i = 0; i < h.probabilities().size(); i++) {
                    double p = calibration.apply(h.probabilities().get(i));
                    sum += (p - y) * (p - y);
                    if (p >= threshold && !(h.times().get(i) >= warnedAt)) {
                        warnedAt = h.times().get(i); // the first forecast at the threshold, unless a clause came first
                    }
                }
                if (!h.probabilities().isEmpty()) {
                    brier += sum / h.probabilities().size();
                    base += (h.baseRate() - y) * (h.baseRate() - y);
                    scored++;
                }
                boolean warning = !Double.isNaN(warnedAt);
                if (violated) {
                    violating++;
                    if (warning) {
                        warned++;
                        leads.add(h.run().timing().violationTime() - warnedAt);
                    }
                } else if (warning) {
                    alarms++;
                }
            }
        }
        return List.of(new Scorecard(property, folds, judged.size(), violating, warned, alarms,
                Scorecard.median(leads), unit, scored == 0 ? Double.NaN : brier / scored,
                scored == 0 ? Double.NaN : base / scored));
    }

    /** The safety property's threshold, NaN when the abstraction has no property. */
    public static double limit(Abstraction abstraction) {
        return abstraction.safety().map(Bound::floor).orElse(Double.NaN);
    }

    /** The safety property's name, null when the abstraction has no property. */
    public static String property(Abstraction abstraction) {
        return abstraction.safety().map(Bound::name).orElse(null);
    }

    /**
     * When the forecast rule warns {@code run} before its violation whatever its threshold, as watch takes the
     * rule's other clauses ({@link ForecastModel#warns}): the thesis's rule ({@link Matching}, each machine matched
     * exactly) when every nominal machine was contradicted and the run has no gap yet ({@link RunTiming#gaps}), or
     * the value below the lowest of the training runs that held once the run is beyond them (a gap, or no nominal
     * machine matching). The time of that warning, NaN when there is none.
     */
    static double warnsAnywayAt(List<LearnedModel> models, ForecastModel stats, int confirm, LogTrace.Run run) {
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
                    return x.time(); // as watch does at a new reading
                }
            }
            if (i == run.pairs().size() || !beforeViolation(run, t.time(i))) {
                return Double.NaN;
            }
            Matching.Step step = matching.pair(run.pairs().get(i));
            if (step.ruleWarns() && step.contradicted() && !gap) {
                return t.time(i);
            }
            if ((gap || !step.nominalAlive()) && stats.belowSafeFloor(t.value(i))) {
                return t.time(i);
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
        return forecast(forecaster, run, new ArrayList<>());
    }

    /** As {@link #forecast(Forecaster, LogTrace.Run)}, and the time of each forecast into {@code times}. */
    private static List<Forecast> forecast(Forecaster forecaster, LogTrace.Run run, List<Double> times) {
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
                times.add(x.time());
            }
            if (i == run.pairs().size()) {
                break;
            }
            if (!beforeViolation(run, t.time(i))) {
                break;
            }
            out.add(forecaster.pair(run.pairs().get(i).input(), run.pairs().get(i).output(), t.time(i), t.value(i),
                    i));
            times.add(t.time(i));
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
