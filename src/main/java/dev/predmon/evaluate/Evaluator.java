package dev.predmon.evaluate;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.Traces;
import net.automatalib.alphabet.Alphabet;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Measures how the predictive monitor would do on a user's own runs: models are learned in memory exactly as
 * {@code learn} learns them ({@link ScenarioLearner#learnSamples}), and every test log is replayed through
 * {@code watch}'s code path ({@link Replay}). Either on a separate test set, or by K-fold cross-validation in
 * which a log is only ever judged by models learned without it ({@link Folds}).
 *
 * <p>Each training log is read once ({@link Traces#read}) and its Mealy sample reused by every fold; nothing is
 * written to disk.
 */
public final class Evaluator {

    private final Abstraction abstraction;
    private final int threshold;
    private final Progress progress;
    private final Alphabet<String> alphabet;

    public Evaluator(Abstraction abstraction, int threshold, Progress progress) {
        this.abstraction = abstraction;
        this.threshold = threshold;
        this.progress = progress;
        this.alphabet = ModelStore.alphabetOf(abstraction);
    }

    /** Learns on {@code train} and judges every log of {@code test}. */
    public Evaluation trainTest(List<ScenarioSpec> train, List<ScenarioSpec> test) throws BadInputException {
        int total = count(train) + 1 + count(test);
        Counter c = new Counter(total);
        List<String> notes = new ArrayList<>();
        Map<Path, MealyTrace> samples = readSamples(train, notes, c);
        ModelSet models = learn(train, samples, log -> true, notes, "");
        c.step("learned " + models.models().size() + " model(s)");
        List<RunResult> runs = new ArrayList<>();
        for (ScenarioSpec s : test) {
            for (Path log : s.logs()) {
                runs.add(judge(log, s, -1, models));
                c.step(log.getFileName().toString());
            }
        }
        return result("test-set", 0, test, runs, notes, models);
    }

    /** K-fold cross-validation over the logs of {@code specs}. */
    public Evaluation crossValidate(List<ScenarioSpec> specs, int k) throws BadInputException {
        Map<Path, Integer> fold = Folds.assign(specs, k);
        Counter c = new Counter(count(specs) * 2 + k + 1);
        List<String> notes = new ArrayList<>();
        Map<Path, MealyTrace> samples = readSamples(specs, notes, c);
        List<RunResult> runs = new ArrayList<>();
        for (int f = 0; f < k; f++) {
            int current = f;
            ModelSet models = learn(specs, samples, log -> fold.get(log) != current, notes, "fold " + f + ": ");
            c.step("fold " + f + ": learned " + models.models().size() + " model(s)");
            for (ScenarioSpec s : specs) {
                for (Path log : s.logs()) {
                    if (fold.get(log) == current) {
                        runs.add(judge(log, s, current, models));
                        c.step("fold " + f + ": " + log.getFileName());
                    }
                }
            }
        }
        ModelSet all = learn(specs, samples, log -> true, new ArrayList<>(), "");
        c.step("learned the models shown, on every log");
        runs.sort(Comparator.comparing(RunResult::scenario).thenComparing(RunResult::log));
        return result("cross-validation", k, specs, runs, notes, all);
    }

    private Evaluation result(String mode, int k, List<ScenarioSpec> judged, List<RunResult> runs, List<String> notes,
                              ModelSet models) {
        List<ScenarioSummary> summaries = new ArrayList<>();
        for (ScenarioSpec s : judged.stream().sorted(Comparator.comparing(ScenarioSpec::name)).toList()) {
            summaries.add(ScenarioSummary.of(s.name(), s.faulty(),
                    runs.stream().filter(r -> r.scenario().equals(s.name())).toList()));
        }
        return new Evaluation(mode, k, threshold, abstraction.name(), List.copyOf(summaries), Confusion.of(runs),
                List.copyOf(runs), List.copyOf(notes), models);
    }

    private RunResult judge(Path log, ScenarioSpec s, int fold, ModelSet models) throws BadInputException {
        try {
            return Replay.run(log, s.name(), s.faulty(), fold, models, abstraction, threshold);
        } catch (IOException e) {
            throw BadInputException.cannotRead(log, e);
        }
    }

    /** Each log's Mealy sample, as {@code learn} makes it; logs without interface messages are left out. */
    private Map<Path, MealyTrace> readSamples(List<ScenarioSpec> specs, List<String> notes, Counter c)
            throws BadInputException {
        Map<Path, MealyTrace> samples = new LinkedHashMap<>();
        for (ScenarioSpec s : specs) {
            for (Path log : s.logs()) {
                LogTrace trace;
                try {
                    trace = Traces.read(log, abstraction);
                } catch (IOException e) {
                    throw BadInputException.cannotRead(log, e);
                }
                if (trace.pairs().isEmpty()) {
                    notes.add(log + ": no skill-component interface message; not learned from");
                } else {
                    samples.put(log, trace.mealy());
                }
                c.step("read " + log.getFileName());
            }
        }
        return samples;
    }

    private ModelSet learn(List<ScenarioSpec> specs, Map<Path, MealyTrace> samples,
                           java.util.function.Predicate<Path> training, List<String> notes, String prefix) {
        List<LearnedScenario> learned = new ArrayList<>();
        for (ScenarioSpec s : specs) {
            List<MealyTrace> own = s.logs().stream().filter(training).filter(samples::containsKey)
                    .map(samples::get).toList();
            if (own.isEmpty()) {
                notes.add(prefix + "scenario '" + s.name() + "' has no training run; its runs can match no model of it");
                continue;
            }
            learned.add(ScenarioLearner.learnSamples(s, own, alphabet));
        }
        return LearnedModels.modelSet(learned, abstraction);
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
