package dev.predmon.evaluate;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.Folds;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.support.SimulatedSets;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Cross-validation and test-set evaluation of small simulated sets: every log judged once and never by models
 * learned on it, the counts and leads add up, verdicts follow their rules, and the JSON has its documented fields.
 */
class EvaluatorTest {

    @TempDir
    static Path dir;
    static List<ScenarioSpec> specs;
    static Evaluation folds;

    @BeforeAll
    static void evaluate() throws Exception {
        specs = ScenarioLayout.scan(SimulatedSets.write(dir.resolve("logs"), 3, 1), AbstractionFiles.defaults());
        folds = new Evaluator(AbstractionFiles.defaults(), 0, Progress.NONE).crossValidate(specs, 3);
    }

    @Test
    void everyLogIsJudgedOnceAndTheCountsAddUp() {
        assertEquals(9, folds.runs().size());
        for (ScenarioSummary s : folds.scenarios()) {
            assertEquals(3, s.runs());
            if (s.faulty()) {
                assertEquals(s.runs(), s.hits() + s.missed() + s.noViolation(), s.toString());
                assertEquals(0, s.falseAlarms());
            } else {
                assertEquals(s.warned(), s.falseAlarms());
                assertEquals(0, s.hits() + s.missed() + s.noViolation());
            }
            assertEquals(s.hits(), s.lead().n());
        }
        Confusion c = folds.confusion();
        assertEquals(9, c.truePositives() + c.falseNegatives() + c.falsePositives() + c.trueNegatives() + c.unscored());
    }

    @Test
    void foldsAreRoundRobinPerScenarioAndNoLogJudgesItself() {
        Map<Path, Integer> fold = Folds.assign(specs, 3);
        for (ScenarioSpec s : specs) {
            List<Path> sorted = s.logs().stream().sorted().toList();
            for (int i = 0; i < sorted.size(); i++) {
                assertEquals(i % 3, fold.get(sorted.get(i)));
            }
        }
        // A run is judged in its own fold, whose models were learned only on the other folds.
        for (RunResult r : folds.runs()) {
            assertEquals(fold.get(r.log().log()), r.fold());
        }
        assertThrows(IllegalArgumentException.class, () -> Folds.assign(specs, 1));
    }

    @Test
    void leadsAreViolationMinusWarningForHitsOnly() {
        for (RunResult r : folds.runs()) {
            if (r.verdict() == Verdict.WARNED_BEFORE_VIOLATION) {
                assertEquals(r.violationTime() - r.warningTime(), r.lead(), 1e-9);
                assertTrue(r.lead() > 0);
            } else {
                assertNull(r.lead());
            }
            if (!r.faulty()) {
                assertNotEquals(Verdict.MISSED, r.verdict());
            }
        }
    }

    @Test
    void verdictRules() {
        assertEquals(Verdict.WARNED_BEFORE_VIOLATION, Verdict.of(true, 1.0, 2.0));
        assertEquals(Verdict.WARNED_LATE, Verdict.of(true, 2.0, 2.0));
        assertEquals(Verdict.MISSED, Verdict.of(true, null, 2.0));
        assertEquals(Verdict.QUIET_NO_VIOLATION, Verdict.of(true, null, null));
        assertEquals(Verdict.FALSE_ALARM, Verdict.of(false, 1.0, null));
        assertEquals(Verdict.QUIET, Verdict.of(false, null, null));
    }

    @Test
    void testSetModeJudgesEveryTestLog() throws Exception {
        List<ScenarioSpec> test = ScenarioLayout.scan(SimulatedSets.write(dir.resolve("test"), 2, 500), AbstractionFiles.defaults());
        Evaluation e = new Evaluator(AbstractionFiles.defaults(), 0, Progress.NONE).trainTest(specs, test);
        assertEquals(6, e.runs().size());
        assertTrue(e.runs().stream().allMatch(r -> r.fold() == -1));
        assertEquals("test-set", e.mode());
    }

    @Test
    void jsonHasTheDocumentedFields() throws Exception {
        JsonNode j = new ObjectMapper().readTree(new ObjectMapper().writeValueAsString(folds));
        for (String f : List.of("mode", "folds", "tolerance", "abstraction", "scenarios", "confusion", "runs", "notes")) {
            assertTrue(j.has(f), f);
        }
        assertFalse(j.has("models"));
        JsonNode s = j.get("scenarios").get(0);
        for (String f : List.of("scenario", "faulty", "runs", "warned", "hits", "falseAlarms", "missed", "late",
                "noViolation", "noMatch", "lead", "valueAtWarning", "batteryAtWarning")) {
            assertTrue(s.has(f), f);
        }
        assertTrue(s.get("lead").has("median"));
        JsonNode r = j.get("runs").get(0);
        for (String f : List.of("scenario", "log", "fold", "verdict", "warningTime", "violationTime", "lead",
                "valueAtWarning", "batteryAtWarning", "noMatch", "eliminations")) {
            assertTrue(r.has(f), f);
        }
        // the older name of valueAtWarning stays, with the same value, for existing scripts
        for (JsonNode x : List.of(s, r)) {
            assertEquals(x.get("valueAtWarning"), x.get("batteryAtWarning"));
        }
        assertTrue(j.get("runs").findValues("valueAtWarning").stream().anyMatch(JsonNode::isNumber));
        assertTrue(j.get("runs").findValuesAsText("verdict").stream().allMatch(v -> v.matches("[a-z-]+")));
    }
}
