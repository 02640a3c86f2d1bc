package dev.predmon.evaluate;

import dev.predmon.pipeline.RunId;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** A deadline's scores beside the elapsed-time baseline's, on hand-made runs. */
class PropertyScoreTest {

    /** A run whose navigation deadline was warned at {@code warning}, went past training at {@code beyond}. */
    private static RunResult run(Double warning, Double violation, Double beyond) {
        return new RunResult("s", false, RunId.of(Path.of("log"), 0, 1), 0, Verdict.QUIET, null, null,
                List.of(), null, null, null, false, null, 10, 5, 0, List.of(), true, "ticks", false, 0, 0, null, null,
                List.of(new RunResult.PropertyResult("navigation-in-time", warning, violation, beyond)));
    }

    @Test
    void theElapsedTimeBaselineIsCountedBesideTheDeadlineRule() {
        List<PropertyScore> scores = PropertyScore.of(List.of(
                run(300.0, 400.0, 270.0),   // both ahead: leads 100 and 130
                run(null, 400.0, 390.0),    // the baseline only: lead 10
                run(null, 400.0, 400.0),    // the baseline at the violation: not ahead
                run(null, null, 300.0),     // a baseline false alarm: a slow navigation that arrived
                run(350.0, null, 280.0),    // a false alarm of both
                run(null, null, null)));
        PropertyScore p = scores.get(0);
        assertEquals("navigation-in-time", p.property());
        assertEquals(List.of(6, 3, 1, 1), List.of(p.runs(), p.violating(), p.warned(), p.falseAlarms()));
        assertEquals(List.of(2, 2), List.of(p.baselineWarned(), p.baselineAlarms()));
        assertEquals(100.0, p.lead().median());
        assertEquals(70.0, p.baselineLead().median());
    }

    /** A run with no evidence for the property is neither a safe run nor a violating one, and its warning no alarm. */
    @Test
    void aRunWithNoEvidenceIsNotCountedAsSafe() {
        RunResult none = new RunResult("s", false, RunId.of(Path.of("log"), 0, 1), 0, Verdict.QUIET, null, null,
                List.of(), null, null, null, false, null, 10, 5, 0, List.of(), true, "ticks", false, 0, 0, null, null,
                List.of(new RunResult.PropertyResult("navigation-in-time", 5.0, null, null, null, null, "no-evidence",
                        "no evidence (no GoTo/goTo command (its trigger) in the run)")));
        PropertyScore p = PropertyScore.of(List.of(run(null, null, null), run(null, 400.0, null), none)).get(0);
        assertEquals(List.of(2, 1, 0, 0, 1), List.of(p.runs(), p.violating(), p.warned(), p.falseAlarms(),
                p.noEvidence()));
    }
}
