package dev.predmon.evaluate;

import dev.predmon.pipeline.RunId;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The raw-value baseline scored beside the warning rule, on hand-made runs. */
class ValueRuleTest {

    /** A run judged with a forecast: warned by the rule at {@code warning}, by the baseline at {@code below}. */
    private static RunResult run(boolean faulty, Double warning, Double violation, Double below) {
        Verdict v = Verdict.of(faulty, warning, violation);
        return new RunResult("s", faulty, RunId.of(java.nio.file.Path.of("log"), 0, 1), 0, v, warning, warning == null ? null : 1L, List.of(), null,
                violation, v == Verdict.WARNED_BEFORE_VIOLATION ? violation - warning : null, false, null, 10, 5, 0,
                List.of(), true, "ticks", false, 0, 0, null,
                new RunResult.ForecastTrace(List.of(0.2), null, null, 0.3, 0.8, below));
    }

    @Test
    void bothRulesAreCountedOnTheSameRunsWithTheirLeads() {
        List<RunResult> runs = List.of(
                run(true, 40.0, 100.0, 70.0),   // both ahead: leads 60 and 30
                run(true, null, 100.0, 90.0),   // the baseline only: lead 10
                run(true, 50.0, 100.0, null),   // the rule only, from the behaviour: lead 50
                run(false, null, null, 20.0),   // a baseline false alarm
                run(false, 30.0, null, null),   // a rule false alarm
                run(false, null, null, null));
        ValueRule judged = ValueRule.judged(runs);
        ValueRule raw = ValueRule.rawValue(runs);
        assertEquals(List.of(2, 3, 1, 3), List.of(judged.warned(), judged.violating(), judged.falseAlarms(),
                judged.held()));
        assertEquals(List.of(2, 3, 1, 3), List.of(raw.warned(), raw.violating(), raw.falseAlarms(), raw.held()));
        assertEquals(55.0, judged.lead().median());
        assertEquals(20.0, raw.lead().median());
    }

    @Test
    void runsWithoutAForecastHaveNoLearnedFloorAndAreLeftOut() {
        RunResult r = run(true, 40.0, 100.0, 70.0);
        RunResult without = new RunResult(r.scenario(), r.faulty(), r.log(), r.fold(), r.verdict(), r.warningTime(),
                r.warningLine(), r.warningScenarios(), r.valueAtWarning(), r.violationTime(), r.lead(), r.noMatch(),
                r.noMatchTime(), r.records(), r.pairs(), r.problems(), r.eliminations(), r.safetyObserved(), r.unit(),
                r.sudden(), r.start(), r.nearBound(), r.beforeViolation());
        assertEquals(0, ValueRule.rawValue(List.of(without)).violating());
    }
}
