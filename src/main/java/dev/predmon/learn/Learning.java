package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.model.ModelIndex;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.pipeline.LogTrace;
import net.automatalib.alphabet.Alphabet;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/** The {@code learn} job as a library call: every scenario of a log directory, then the models written. */
public final class Learning {

    private Learning() {
    }

    /**
     * What a learn made.
     *
     * @param scenarios every scenario learned, sorted by name
     * @param notes     what the user should know about the model directory (usually nothing)
     * @param evidence  what the training logs say of each property: names no log holds, and how many runs violated
     *                  it or gave no evidence for it
     */
    public record Result(List<LearnedScenario> scenarios, List<String> notes, ForecastModel forecast,
                         TrainingEvidence evidence) {

        /** A result without the properties' evidence. */
        public Result(List<LearnedScenario> scenarios, List<String> notes, ForecastModel forecast) {
            this(scenarios, notes, forecast, new TrainingEvidence(List.of(), List.of()));
        }
    }

    /**
     * Learns every scenario under {@code logs} and replaces {@code models} atomically. Whether {@code models} may
     * be replaced (new, empty or written by predmon; not the logs) is checked before learning starts, so a refusal
     * comes at once and changes nothing.
     *
     * @param each receives each scenario as soon as it is learned (for progress and reports)
     */
    public static Result learnAndWrite(Path logs, Path models, Abstraction abstraction, Consumer<LearnedScenario> each)
            throws BadInputException, IOException {
        return learnAndWrite(logs, models, abstraction, each, step -> { });
    }

    /**
     * As above; {@code step} is told each step of replacing the model directory before it is taken
     * ({@link ModelStore#write(Path, ModelIndex, Map, String, ForecastModel, Consumer)}), so that a
     * test can kill a learn at each.
     */
    public static Result learnAndWrite(Path logs, Path models, Abstraction abstraction, Consumer<LearnedScenario> each,
                                       Consumer<String> step) throws BadInputException, IOException {
        ModelStore.checkWritable(models, logs);
        List<ScenarioSpec> specs = ScenarioLayout.scan(logs, abstraction);
        List<Path> all = specs.stream().flatMap(s -> s.logs().stream()).toList();
        Map<Path, LogTrace> traces = ScenarioLearner.read(all, abstraction);
        Learned learned = learn(specs, traces, abstraction, abstraction.confirm(),
                tuned -> ScenarioLearner.read(all, tuned), null, each);
        List<String> notes = ModelStore.write(models, LearnedModels.index(learned.scenarios(), learned.tuned()),
                LearnedModels.dots(learned.scenarios(), MealyAlphabet.inputs(abstraction)), abstraction.canonicalJson(),
                learned.forecast(), step);
        return new Result(learned.scenarios(), notes, learned.forecast(),
                TrainingEvidence.of(specs, traces, abstraction.properties(), abstraction.format()));
    }

    /**
     * What the recipe made: every scenario's machines, the abstraction tuned to the training runs' noise, and the
     * forecast.
     */
    public record Learned(List<LearnedScenario> scenarios, Abstraction tuned, ForecastModel forecast) {

        /** The models in memory, as {@code watch} would load them from the directory {@code learn} writes. */
        public ModelSet modelSet() {
            return LearnedModels.modelSet(scenarios, tuned, forecast);
        }
    }

    /** Reads the training logs again with a tuned abstraction. */
    @FunctionalInterface
    public interface Reread {
        Map<Path, LogTrace> read(Abstraction tuned) throws BadInputException;
    }

    /**
     * The one recipe of {@code learn} and {@code evaluate}: the sensor noise estimated from the runs of {@code specs}
     * ({@link #tuneToNoise}), their logs read again with the hysteresis that absorbs it ({@code reread}), each
     * scenario learned ({@link ScenarioLearner#learn}), then its forecast, threshold and scorecard
     * ({@link ForecastTraining#train}).
     *
     * @param traces  the logs of {@code specs} read with {@code abstraction}
     * @param notes   where a scenario without a training run is noted and left out; null: such a scenario is an error
     * @param each    receives each scenario as soon as it is learned
     */
    public static Learned learn(List<ScenarioSpec> specs, Map<Path, LogTrace> traces, Abstraction abstraction,
                                int confirm, Reread reread, List<String> notes, Consumer<LearnedScenario> each)
            throws BadInputException {
        Abstraction tuned = tuneToNoise(specs, traces, abstraction);
        Map<Path, LogTrace> read = tuned == abstraction ? traces : reread.read(tuned); // the hysteresis changes them
        List<LearnedScenario> learned = new ArrayList<>();
        List<ScenarioSpec> learnedSpecs = new ArrayList<>();
        for (ScenarioSpec s : specs) {
            if (notes != null && s.logs().stream().allMatch(log -> read.get(log).samples(s.runs()).isEmpty())) {
                notes.add("scenario '" + s.name() + "' has no training run; its runs can match no model of it");
                continue;
            }
            LearnedScenario l = ScenarioLearner.learn(s, tuned, read);
            each.accept(l);
            learned.add(l);
            learnedSpecs.add(s);
        }
        Alphabet<String> alphabet = MealyAlphabet.inputs(abstraction);
        HeldOutFolds heldOut = ForecastTraining.heldOut(learnedSpecs, read, alphabet, tuned, confirm);
        ForecastModel forecast = DeadlineTraining.train(ForecastTraining.train(learnedSpecs, read,
                LearnedModels.machines(learned), tuned, heldOut), heldOut, tuned);
        return new Learned(List.copyOf(learned), tuned, forecast);
    }

    /**
     * {@code abstraction} with the hysteresis that absorbs the noise of its continuous sensors, estimated from the
     * runs the scenarios learn from ({@link NoiseEstimate}); itself when they show no noise.
     */
    public static Abstraction tuneToNoise(List<ScenarioSpec> specs, Map<Path, LogTrace> traces, Abstraction abstraction) {
        List<LogTrace.Run> runs = new ArrayList<>();
        for (ScenarioSpec s : specs) {
            for (Path log : s.logs()) {
                LogTrace t = traces.get(log);
                if (t != null) {
                    t.runs().stream().filter(r -> s.runs().selects(r.violated())).forEach(runs::add);
                }
            }
        }
        return abstraction.withLearnedHysteresis(NoiseEstimate.hysteresis(runs));
    }
}
