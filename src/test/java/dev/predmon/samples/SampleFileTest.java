package dev.predmon.samples;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.support.SimulatedSets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The sample files of {@code export-samples}: what is written reads back as the words learn gave LearnLib. */
class SampleFileTest {

    @TempDir
    Path dir;

    @Test
    void exportedSamplesParseBackToTheWordsLearnUses() throws Exception {
        Path logs = SimulatedSets.write(dir.resolve("logs"), 2, 1);
        Abstraction a = AbstractionFiles.defaults();
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
        BadInputException e = assertThrows(BadInputException.class,
                () -> SampleFile.read(f));
        assertTrue(e.getMessage().contains(":2:"), e.getMessage());
    }
}
