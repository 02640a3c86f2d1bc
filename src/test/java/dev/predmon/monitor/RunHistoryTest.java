package dev.predmon.monitor;

import dev.predmon.parse.Clock;
import dev.predmon.property.Absence;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.Scope;
import dev.predmon.property.Verdict;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class RunHistoryTest {

    private static RunOutcome run(int n, boolean warned, boolean noMatch) {
        MonitorEvent.Warning w = warned ? new MonitorEvent.Warning(n, n, List.of("depleted"), 30.0, 5, Clock.SECONDS, n)
                : null;
        return new RunOutcome(n, n * 10L + 1, w, null, noMatch, 7, true);
    }

    @Test
    void aWatchOfThousandsOfRunsKeepsTheLatestAndCountsThemAll() {
        RunHistory h = new RunHistory();
        h.add(run(0, true, false)); // the only warning, long before the runs still listed
        for (int i = 1; i < 2500; i++) {
            h.add(run(i, false, false));
        }
        List<RunOutcome> listed = h.withCurrent(run(2500, false, false));
        assertEquals(RunHistory.KEPT + 1, listed.size(), "bounded: the latest runs and the current one");
        assertEquals(2500, listed.get(listed.size() - 1).run());
        assertEquals(1500, listed.get(0).run(), "the oldest are the ones no longer listed");
        RunsSummary all = h.summary(run(2500, false, false));
        assertEquals(2501, all.runs());
        assertEquals(1500, all.dropped());
        assertEquals(2501 * 7L, all.pairs(), "pairs of every run, listed or not");
        assertTrue(all.warnedMatching(), "a warning in a run no longer listed still makes the log's verdict");
        assertEquals(0, all.firstWarned().orElseThrow().run());
        assertFalse(all.noMatch());
    }

    @Test
    void theCurrentRunCountsToo() {
        RunHistory h = new RunHistory();
        h.add(run(0, false, false));
        RunsSummary s = h.summary(run(1, true, true));
        assertEquals(2, s.runs());
        assertTrue(s.noMatch());
        assertFalse(s.warnedMatching(), "a run warned and then lost by every model is a no-match run");
        assertEquals(1, s.firstWarned().orElseThrow().run());
        assertEquals(0, s.dropped());
    }

    /** A violation of {@code property} at {@code line}, as the safety monitor's verdict on the run gives it. */
    private static PropertyChecker.PropertyVerdict violated(String property, long line) {
        Property p = new Absence(property, property, null, Scope.GLOBAL, null);
        return new PropertyChecker.PropertyVerdict(p, new Verdict.Violated(line, line, null, null, "aborted"));
    }

    private static MonitorEvent.Warning deadlineWarning(long line) {
        return new MonitorEvent.Warning(line, line, List.of(), 60.0, 3, Clock.TICKS, 0, WarningRule.FORECAST, null,
                "navigation pending long", MonitorEvent.Clause.DEADLINE, null, "navigation-in-time");
    }

    /** Every property's warnings and violations count: a deadline's warning is a warning, an abort a violation. */
    @Test
    void theVerdictCountsEveryPropertyNotOnlyTheForecasts() {
        RunOutcome abortedUnwarned = new RunOutcome(0, 1, null, null, false, 7, true, null,
                List.of(violated("no-abort", 40)));
        assertTrue(abortedUnwarned.unwarnedViolation(), "an abort with no warning of any property before it");
        assertFalse(abortedUnwarned.warned());

        RunOutcome deadlineFirst = new RunOutcome(0, 1, null, null, false, 7, true, null,
                List.of(violated("no-abort", 40)), deadlineWarning(30));
        assertFalse(deadlineFirst.unwarnedViolation(), "a deadline's warning at line 30 came before the abort");
        assertTrue(deadlineFirst.warned());

        RunOutcome deadlineAtTheAbort = new RunOutcome(0, 1, null, null, false, 7, true, null,
                List.of(violated("no-abort", 40)), deadlineWarning(40));
        assertTrue(deadlineAtTheAbort.unwarnedViolation(), "a warning at the violating record predicts nothing");

        RunHistory h = new RunHistory();
        h.add(deadlineFirst);
        RunsSummary s = h.summary(run(1, false, false));
        assertTrue(s.warned() && s.warnedMatching(), "the deadline's warning is the log's");
        assertFalse(s.unwarnedViolation());
        assertTrue(h.summary(abortedUnwarned).unwarnedViolation());
    }

    /**
     * Two writers after a rename rotation: a run holds records of two files, each numbered in its own. The abort read
     * first (the renamed file's line 8996) and the deadline's warning read later (the new file's line 7127): the
     * violation came with no warning before it, whatever their lines say. Read the other way round, it was warned.
     */
    @Test
    void beforeIsTheOrderOfReadingNotTheLines() {
        RunOutcome abortReadFirst = new RunOutcome(0, 1, null, null, false, 7, true, null,
                List.of(violated("no-abort", 8996)), deadlineWarning(7127), Map.of(), 20_000, 10_000);
        assertTrue(abortReadFirst.unwarnedViolation(), "the warning came 10,000 records after the abort");
        RunOutcome warningReadFirst = new RunOutcome(0, 1, null, null, false, 7, true, null,
                List.of(violated("no-abort", 7127)), deadlineWarning(8996), Map.of(), 10_000, 20_000);
        assertFalse(warningReadFirst.unwarnedViolation(), "the warning was read 10,000 records before the abort");
        RunOutcome sameRecord = new RunOutcome(0, 1, null, null, false, 7, true, null,
                List.of(violated("no-abort", 8996)), deadlineWarning(8996), Map.of(), 10_000, 10_000);
        assertTrue(sameRecord.unwarnedViolation(), "a warning at the violating record predicts nothing");
    }
}
