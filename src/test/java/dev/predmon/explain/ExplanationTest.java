package dev.predmon.explain;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.pipeline.Traces;
import dev.predmon.samples.SampleFile;
import dev.predmon.support.HandRuns;
import dev.predmon.support.SimulatedSets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ExplanationTest {

    @TempDir
    Path dir;

    @Test
    void namesTheModelAndTheExpectedAndSeenSymbols() throws Exception {
        Abstraction a = Abstraction.defaults();
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
        return ScenarioLearner.learnSamples(spec, List.of(t), ModelStore.alphabetOf(a));
    }

    @Test
    void exportedSamplesParseBackToTheWordsLearnUses() throws Exception {
        Path logs = SimulatedSets.write(dir.resolve("logs"), 2, 1);
        Abstraction a = Abstraction.defaults();
        for (ScenarioSpec s : ScenarioLayout.scan(logs, a)) {
            LearnedScenario l = ScenarioLearner.learn(s, a);
            Path file = dir.resolve(s.name() + ".txt");
            Files.writeString(file, SampleFile.text(l));
            List<MealyTrace> back = SampleFile.read(file);
            List<MealyTrace> learned = LearnedModels.samples(l);
            assertEquals(learned.size(), back.size());
            for (int i = 0; i < back.size(); i++) {
                assertEquals(learned.get(i).inputs(), back.get(i).inputs());
                assertEquals(learned.get(i).outputs(), back.get(i).outputs());
            }
        }
    }

    @Test
    void aBrokenSampleLineIsReportedWithItsLine() throws Exception {
        Path f = dir.resolve("bad.txt");
        Files.writeString(f, "# c\na/OK b\n");
        BadInputException e = org.junit.jupiter.api.Assertions.assertThrows(BadInputException.class,
                () -> SampleFile.read(f));
        assertTrue(e.getMessage().contains(":2:"), e.getMessage());
    }
}
