package dev.predmon.evaluate;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.model.ModelSet;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.pipeline.Traces;
import dev.predmon.support.HandRuns;
import dev.predmon.support.Records;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What a replay measures besides the verdict: when the run started, and how many readings lay near the bound before
 * the violation, which is what makes a violation sudden or approached.
 */
class ReplayTest {

    private static final Abstraction A = AbstractionFiles.defaults();

    @TempDir
    Path dir;
    ModelSet models;

    @BeforeEach
    void learn() throws Exception {
        Path recharge = Files.writeString(dir.resolve("recharge.log"), HandRuns.recharge().text());
        ScenarioSpec spec = new ScenarioSpec("recharge", false, "", List.of(recharge));
        models = LearnedModels.modelSet(List.of(ScenarioLearner.learnSamples(spec,
                List.of(Traces.read(recharge, A).mealy()), MealyAlphabet.inputs(A))), A);
    }

    private RunResult replay(String name, Records r) throws Exception {
        Path log = Files.writeString(dir.resolve(name), r.text());
        List<RunResult> runs = Replay.run(log, "depleted", true, RunLabel.ALL, -1, models, A, 0, A.confirm());
        assertEquals(1, runs.size());
        return runs.get(0);
    }

    @Test
    void aFallStraightPastTheBandIsSuddenWithNoReadingNearTheBound() throws Exception {
        RunResult r = replay("jump.log", new Records().at(5).level(80).at(6).level(65).at(7).level(10));
        assertEquals(0, r.nearBound());
        assertTrue(r.sudden());
        // Records stamps each record a millisecond after the one before.
        assertEquals(5, r.start(), 0.01);
        assertEquals(2, r.sinceStart(r.violationTime()), 0.01);
    }

    @Test
    void tenReadingsInTheBandBeforeTheViolationMakeItApproached() throws Exception {
        Records r = new Records().at(0).level(60);
        for (int i = 0; i < RunResult.SUDDEN_READINGS; i++) {
            r.at(1 + i).level(29.5 - i);
        }
        RunResult approached = replay("slow.log", r.at(11).level(19).at(12).level(25));
        assertEquals(RunResult.SUDDEN_READINGS, approached.nearBound(), "a reading after the violation is not counted");
        assertFalse(approached.sudden());
    }

    @Test
    void fewerReadingsInTheBandStillMakeItSudden() throws Exception {
        // The hand-written depleted run: 28 and 23 lie within 10 points above 20, then 18.
        RunResult r = replay("depleted.log", HandRuns.depleted());
        assertEquals(2, r.nearBound());
        assertTrue(r.sudden());
    }

    @Test
    void aRunWithoutViolationIsNeverSuddenAndCountsItsLastApproach() throws Exception {
        RunResult r = replay("low.log", new Records().at(1e9).level(40).at(1e9 + 1).level(25).at(1e9 + 2).level(22));
        assertEquals(2, r.nearBound());
        assertFalse(r.sudden());
        assertEquals(1e9, r.start(), 0.01, "an epoch log's run starts at its first record");
    }

    @Test
    void aDipThatRecoveredIsNoApproachToALaterViolation() throws Exception {
        Records r = new Records().at(0).level(60);
        for (int i = 0; i < 2 * RunResult.SUDDEN_READINGS; i++) {
            r.at(1 + i).level(25);
        }
        // Recharged to 80, then set by hand to 10: the twenty readings at 25 before the recharge do not count.
        RunResult jump = replay("dip.log", r.at(21).level(80).at(22).level(10));
        assertEquals(0, jump.nearBound());
        assertTrue(jump.sudden());
    }
}
