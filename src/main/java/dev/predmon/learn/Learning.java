package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.model.ModelIndex;
import dev.predmon.model.ModelStore;
import dev.predmon.pipeline.LogTrace;

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
     */
    public record Result(List<LearnedScenario> scenarios, List<String> notes, ForecastModel forecast) {
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
        List<LearnedScenario> learned = new ArrayList<>();
        List<ScenarioSpec> specs = ScenarioLayout.scan(logs, abstraction);
        List<Path> all = specs.stream().flatMap(s -> s.logs().stream()).toList();
        Map<Path, LogTrace> traces = ScenarioLearner.read(all, abstraction);
        Abstraction tuned = tuneToNoise(specs, traces, abstraction);
        if (tuned != abstraction) {
            traces = ScenarioLearner.read(all, tuned); // the hysteresis changes the traces
        }
        for (ScenarioSpec s : specs) {
            LearnedScenario l = ScenarioLearner.learn(s, tuned, traces);
            each.accept(l);
            learned.add(l);
        }
        ForecastModel forecast = DeadlineTraining.train(ForecastTraining.train(specs, traces,
                LearnedModels.machines(learned), MealyAlphabet.inputs(abstraction), ForecastTraining.limit(tuned),
                ForecastTraining.property(tuned), tuned.confirm()), specs, traces, tuned);
        List<String> notes = ModelStore.write(models, LearnedModels.index(learned, tuned),
                LearnedModels.dots(learned, MealyAlphabet.inputs(abstraction)), abstraction.canonicalJson(), forecast, step);
        return new Result(List.copyOf(learned), notes, forecast);
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
