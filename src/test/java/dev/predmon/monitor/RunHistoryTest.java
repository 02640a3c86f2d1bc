package dev.predmon.monitor;

import dev.predmon.parse.Clock;
import org.junit.jupiter.api.Test;

import java.util.List;

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
}
