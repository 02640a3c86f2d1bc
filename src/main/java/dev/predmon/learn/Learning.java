package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelStore;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
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
    public record Result(List<LearnedScenario> scenarios, List<String> notes) {
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
        ModelStore.checkWritable(models, logs);
        List<LearnedScenario> learned = new ArrayList<>();
        for (ScenarioSpec s : ScenarioLayout.scan(logs)) {
            LearnedScenario l = ScenarioLearner.learn(s, abstraction);
            each.accept(l);
            learned.add(l);
        }
        List<String> notes = ModelStore.write(models, LearnedModels.index(learned, abstraction),
                LearnedModels.dots(learned, ModelStore.alphabetOf(abstraction)), abstraction.canonicalJson());
        return new Result(List.copyOf(learned), notes);
    }
}
