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
     * Learns every scenario under {@code logs} and replaces {@code models} atomically.
     *
     * @param each receives each scenario as soon as it is learned (for progress and reports)
     */
    public static List<LearnedScenario> learnAndWrite(Path logs, Path models, Abstraction abstraction,
                                                      Consumer<LearnedScenario> each) throws BadInputException, IOException {
        List<LearnedScenario> learned = new ArrayList<>();
        for (ScenarioSpec s : ScenarioLayout.scan(logs, abstraction)) {
            LearnedScenario l = ScenarioLearner.learn(s, abstraction);
            each.accept(l);
            learned.add(l);
        }
        ModelStore.write(models, LearnedModels.index(learned, abstraction),
                LearnedModels.dots(learned, ModelStore.alphabetOf(abstraction)));
        return List.copyOf(learned);
    }
}
