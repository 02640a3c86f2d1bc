package dev.predmon.evaluate;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.learn.Folds;
import dev.predmon.learn.Learning;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.WarningRule;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.Traces;
import dev.predmon.property.Property;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;

/**
 * Measures how the predictive monitor would do on a user's own runs: models are learned in memory exactly as
 * {@code learn} learns them (one recipe: {@link Learning#learn}), and every test log is replayed through
 * {@code watch}'s code path ({@link Replay}). Either on a separate test set, or by K-fold cross-validation in
 * which a log is only ever judged by models learned without it ({@link Folds}).
 *
 * <p>Each training log is read once ({@link Traces#read}) and its Mealy sample reused by every fold; nothing is
 * written to disk.
 */
public final class Evaluator {

    private final Abstraction abstraction;
    private final int tolerance;
    private final int confirm;
    /** Training traces read again with a learned hysteresis, by that hysteresis. */
    private final Map<Map<String, Double>, Map<Path, LogTrace>> retuned = new HashMap<>();
    private final Progress progress;
    private WarningRule rule;

    public Evaluator(Abstraction abstraction, int tolerance, Progress progress) {
        this(abstraction, tolerance, abstraction.confirm(), progress);
    }

    /** @param confirm pairs a faulty model must match after the last nominal model is eliminated (see watch) */
    public Evaluator(Abstraction abstraction, int tolerance, int confirm, Progress progress) {
        this.confirm = confirm;
        this.abstraction = abstraction;
        this.tolerance = tolerance;
        this.progress = progress;
    }

    /** Judges by {@code rule} instead of the models' default ({@link PredictiveMonitor#defaultRule}). */
    public Evaluator rule(WarningRule rule) {
        this.rule = rule;
        return this;
    }

    /** Learns on {@code train} and judges every log of {@code test}. */
    public Evaluation trainTest(List<ScenarioSpec> train, List<ScenarioSpec> test) throws BadInputException {
        int total = count(train) + 1 + count(test);
        Counter c = new Counter(total);
        List<String> notes = new ArrayList<>();
        Map<Path, LogTrace> samples = readSamples(train, notes, c);
        ModelSet models = learn(train, samples, log -> true, notes, "");
        Map<String, Double> rates = baseRates(train, samples, log -> true);
        c.step("learned " + models.models().size() + " model(s)");
        List<RunResult> runs = new ArrayList<>();
        for (ScenarioSpec s : test) {
            for (Path log : s.logs()) {
                runs.addAll(judge(log, s, -1, models, rates));
                c.step(log.getFileName().toString());
            }
        }
        return result("test-set", 0, test, runs, notes, models);
    }

    /** K-fold cross-validation over the logs of {@code specs}. */
    public Evaluation crossValidate(List<ScenarioSpec> specs, int k) throws BadInputException {
        Map<Path, Integer> fold = Folds.assign(specs, k);
        int used = Folds.used(fold);
        Counter c = new Counter(count(specs) * 2 + used + 1);
        List<String> notes = new ArrayList<>();
        Folds.instead(fold, k).ifPresent(notes::add);
        Map<Path, LogTrace> samples = readSamples(specs, notes, c);
        List<RunResult> runs = new ArrayList<>();
        for (int f = 0; f < used; f++) {
            int current = f;
            ModelSet models = learn(specs, samples, log -> fold.get(log) != current, notes, "fold " + f + ": ");
            Map<String, Double> rates = baseRates(specs, samples, log -> fold.get(log) != current);
            c.step("fold " + f + ": learned " + models.models().size() + " model(s)");
            for (ScenarioSpec s : specs) {
                for (Path log : s.logs()) {
                    if (fold.get(log) == current) {
                        runs.addAll(judge(log, s, current, models, rates));
                        c.step("fold " + f + ": " + log.getFileName());
                    }
                }
            }
        }
        ModelSet all = learn(specs, samples, log -> true, new ArrayList<>(), "");
        c.step("learned the models shown, on every log");
        runs.sort(Comparator.comparing(RunResult::scenario).thenComparing(r -> r.log().name()));
        return result("cross-validation", used, specs, runs, notes, all);
    }

    private Evaluation result(String mode, int k, List<ScenarioSpec> judged, List<RunResult> runs, List<String> notes,
                              ModelSet models) {
        List<ScenarioSummary> summaries = new ArrayList<>();
        for (ScenarioSpec s : judged.stream().sorted(Comparator.comparing(ScenarioSpec::name)).toList()) {
            summaries.add(ScenarioSummary.of(s.name(), s.faulty(),
                    runs.stream().filter(r -> r.scenario().equals(s.name())).toList()));
        }
        return new Evaluation(mode, k, tolerance, abstraction.name(), List.copyOf(summaries), Confusion.of(runs),
                List.copyOf(runs), List.copyOf(notes), models, ruleFor(models).id(), ForecastScore.of(runs));
    }

    private List<RunResult> judge(Path log, ScenarioSpec s, int fold, ModelSet models, Map<String, Double> rates)
            throws BadInputException {
        try {
            return Replay.run(log, s.name(), s.faulty(), s.runs(), fold, models, abstraction, tolerance, confirm,
                    ruleFor(models), rates);
        } catch (IOException e) {
            throw BadInputException.cannotRead(log, e);
        }
    }

    /** Each log's trace, read once, its runs' Mealy samples taken as {@code learn} takes them. */
    private Map<Path, LogTrace> readSamples(List<ScenarioSpec> specs, List<String> notes, Counter c)
            throws BadInputException {
        Map<Path, LogTrace> samples = new LinkedHashMap<>();
        // Read on every core, then taken in order: the samples do not depend on the thread count.
        List<Path> logs = specs.stream().flatMap(s -> s.logs().stream()).toList();
        Map<Path, LogTrace> read = ScenarioLearner.read(logs, abstraction, log -> c.step("read " + log.getFileName()));
        for (int repeated = logs.size() - read.size(); repeated > 0; repeated--) {
            c.step("read"); // a log named twice is read once but counted twice
        }
        for (ScenarioSpec s : specs) {
            for (Path log : s.logs()) {
                LogTrace trace = read.get(log);
                if (trace.samples(s.runs()).isEmpty()) {
                    notes.add(log + ": no skill-component interface message; not learned from");
                } else {
                    samples.put(log, trace);
                }
            }
        }
        return samples;
    }

    /**
     * Learns every scenario from the training logs, as {@code learn} does: the sensor noise is estimated from the
     * training runs ({@link Learning#tuneToNoise}) and, when there is some, the logs are read again with the
     * hysteresis that absorbs it (cached by hysteresis, since folds mostly agree).
     */
    private ModelSet learn(List<ScenarioSpec> specs, Map<Path, LogTrace> samples,
                           Predicate<Path> training, List<String> notes, String prefix)
            throws BadInputException {
        List<ScenarioSpec> train = specs.stream().map(s -> s.withLogs(s.logs().stream().filter(training).filter(samples::containsKey).toList())).toList();
        List<String> said = new ArrayList<>();
        Learning.Learned learned = Learning.learn(train, samples, abstraction, confirm,
                tuned -> reread(samples, tuned), said, l -> { });
        said.forEach(n -> notes.add(prefix + n));
        return learned.modelSet();
    }

    /**
     * The base rate of every property but the forecast's: the share of the training runs (the runs of the logs
     * {@code training} keeps that their scenario learns from) that violated it, with the forecast's prior of
     * {@link ForecastModel#PRIOR_RUNS} runs split evenly, so that it is the battery's base rate taken for each property.
     */
    private Map<String, Double> baseRates(List<ScenarioSpec> specs, Map<Path, LogTrace> samples,
                                          Predicate<Path> training) {
        int runs = 0;
        Map<String, Integer> violating = new HashMap<>();
        for (ScenarioSpec s : specs) {
            for (Path log : s.logs()) {
                LogTrace trace = samples.get(log);
                if (trace == null || !training.test(log)) {
                    continue;
                }
                for (LogTrace.Run r : trace.judgedRunsInFull()) {
                    if (!s.runs().selects(r.violated())) {
                        continue;
                    }
                    runs++;
                    for (Property p : abstraction.properties()) {
                        violating.merge(p.id(), r.violated(p.id()) ? 1 : 0, Integer::sum);
                    }
                }
            }
        }
        Map<String, Double> rates = new LinkedHashMap<>();
        for (Property p : abstraction.properties()) {
            rates.put(p.id(), (violating.getOrDefault(p.id(), 0) + ForecastModel.PRIOR_RUNS / 2)
                    / (runs + ForecastModel.PRIOR_RUNS));
        }
        return rates;
    }

    /** The training logs read again with {@code tuned}, cached by hysteresis, since folds mostly agree. */
    private Map<Path, LogTrace> reread(Map<Path, LogTrace> samples, Abstraction tuned) throws BadInputException {
        Map<Path, LogTrace> traces = retuned.get(tuned.learnedHysteresis());
        if (traces == null) {
            traces = ScenarioLearner.read(samples.keySet(), tuned);
            retuned.put(tuned.learnedHysteresis(), traces);
        }
        return traces;
    }

    private WarningRule ruleFor(ModelSet models) {
        return rule != null ? rule : PredictiveMonitor.defaultRule(models);
    }

    private static int count(List<ScenarioSpec> specs) {
        return specs.stream().mapToInt(s -> s.logs().size()).sum();
    }

    private final class Counter {
        private final int total;
        private int done;

        Counter(int total) {
            this.total = total;
        }

        void step(String what) {
            progress.step(++done, total, what);
        }
    }
}
