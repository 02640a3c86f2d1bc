package dev.predmon.explain;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.pipeline.Traces;
import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** What {@code explain} says of a run: which model stopped matching where, and the symbols it expected and saw. */
class ExplanationTest {

    @TempDir
    Path dir;

    @Test
    void namesTheModelAndTheExpectedAndSeenSymbols() throws Exception {
        Abstraction a = AbstractionFiles.defaults();
        Path recharge = dir.resolve("recharge.log");
        Path depleted = dir.resolve("depleted.log");
        Files.writeString(recharge, HandRuns.recharge().text());
        Files.writeString(depleted, HandRuns.depleted().text());
        ModelSet models = LearnedModels.modelSet(List.of(
                learn("recharge", false, recharge, a), learn("depleted", true, depleted, a)), a);

        List<Explanation> runs = Explanation.of(depleted, models, a, 0, a.confirm());
        assertEquals(1, runs.size(), "a log of one run is one explanation");
        Explanation x = runs.get(0);
        assertFalse(x.steps().isEmpty());
        Explanation.ModelFate rechargeFate = x.models().stream().filter(f -> f.model().equals("recharge"))
                .findFirst().orElseThrow();
        assertFalse(rechargeFate.matched());
        assertNotNull(rechargeFate.stoppedAt());
        Explanation.Step at = x.steps().get(rechargeFate.stoppedAt());
        assertEquals(at.input(), rechargeFate.input());
        if (rechargeFate.expected() != null) {
            assertEquals(at.output(), rechargeFate.seen());
            assertTrue(rechargeFate.reason().contains(rechargeFate.expected()));
            assertTrue(rechargeFate.reason().contains(rechargeFate.seen()));
        }
        assertTrue(x.models().stream().anyMatch(f -> f.model().equals("depleted") && f.matched()));
        assertNotNull(x.run().warningTime(), "the depleted run is warned");
    }

    private static LearnedScenario learn(String name, boolean faulty, Path log, Abstraction a) throws Exception {
        ScenarioSpec spec = new ScenarioSpec(name, faulty, "", List.of(log));
        MealyTrace t = Traces.read(log, a).mealy();
        return ScenarioLearner.learnSamples(spec, List.of(t), MealyAlphabet.inputs(a));
    }
}
