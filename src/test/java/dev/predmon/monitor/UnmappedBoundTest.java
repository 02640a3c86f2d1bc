package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.pipeline.UnmappedCounts;
import dev.predmon.pipeline.UnmappedMessages;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A followed log whose mapped command replies with a new value every time (a pose, a counter) keeps the monitor's
 * memory bounded, as the run history is: the first {@value UnmappedCounts#KINDS} kinds apart, the rest counted by
 * command, every message counted, across restarts too.
 */
class UnmappedBoundTest {

    private static final Abstraction THESIS = AbstractionFiles.builtin("thesis").orElseThrow();

    private static LogRecord status(long i) {
        return new LogRecord(i + 1, i * 0.01, "DEBUG", RecordKind.REPLY, "/client", "/GoTo", "GoTo", "getStatus",
                "kitchen", Long.toString(1_000_000 + i));
    }

    @Test
    void twoHundredThousandDistinctRepliesAreCountedInBoundedMemory() {
        List<UnmappedMessage> firstSightings = new ArrayList<>();
        PredictiveMonitor m = new PredictiveMonitor(LearnedModels.modelSet(List.of(), THESIS), THESIS, 0, e -> {
            if (e instanceof MonitorEvent.Unmapped u) {
                firstSightings.add(u.message());
            }
        });
        long n = 0;
        for (int file = 0; file < 4; file++) { // three rotations: the totals before them are bounded too
            for (int i = 0; i < 50_000; i++) {
                m.accept(status(n++));
            }
            if (file < 3) {
                m.restart("replaced");
            }
        }
        Map<UnmappedMessage, Long> unmapped = m.unmapped();
        assertEquals(200_000, unmapped.values().stream().mapToLong(Long::longValue).sum(), "every message counted");
        assertTrue(unmapped.size() <= UnmappedCounts.KINDS + 1, "kinds kept: " + unmapped.size());
        assertEquals(UnmappedCounts.KINDS + 1, unmapped.size());
        UnmappedMessage other = new UnmappedMessage("GoTo", "getStatus", UnmappedMessage.Kind.OTHER_VALUES, "");
        assertEquals("GoTo/getStatus (other values)", other.text());
        assertEquals(199_000, unmapped.get(other));
        assertTrue(firstSightings.size() <= 4 * (UnmappedCounts.KINDS + 1), "first sightings: " + firstSightings.size());
        String line = UnmappedMessages.lines(unmapped).get(0);
        assertEquals("GoTo/getStatus (200000 messages): 1000 distinct replies no rule takes; more distinct messages "
                + "than are told apart", line);
    }
}
