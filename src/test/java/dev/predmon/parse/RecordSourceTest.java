package dev.predmon.parse;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The YARP format through the input seam: a log read once and the same log followed and drained give the same
 * records, problems and line count; a source read once reads at its first poll and never again.
 */
class RecordSourceTest {

    @TempDir
    Path dir;

    @Test
    void readOnceAndFollowedGiveTheSameRecordsProblemsAndLines() throws IOException {
        // a record cut at the end: reported once as a problem by both
        String text = SampleLogs.mixed(50, 3) + "1.0\tDEBUG\tCommand intercepted:\n  From      : /a\n";
        Path log = Files.writeString(dir.resolve("a.log"), text);
        List<Object> once = new ArrayList<>();
        List<Object> followed = new ArrayList<>();
        long onceLines;
        try (RecordSource s = LogFormat.yarp().read(log, RecordSink.of(once::add, once::add))) {
            assertTrue(s.poll());
            assertFalse(s.poll(), "read once");
            s.drain();
            onceLines = s.lines();
        }
        try (RecordSource s = LogFormat.yarp().follow(log, RecordSink.of(followed::add, followed::add))) {
            s.drain();
            assertEquals(onceLines, s.lines());
        }
        assertEquals(text.lines().count(), onceLines);
        assertEquals(51, once.size(), "50 records and the cut one's problem");
        assertTrue(once.get(50) instanceof ParseProblem, once.get(50).toString());
        assertEquals(once, followed);
    }

    @Test
    void aMissingLogIsAnErrorBothWays() {
        Path missing = dir.resolve("missing.log");
        RecordSink ignore = RecordSink.of(r -> { }, p -> { });
        assertThrows(NoSuchFileException.class, () -> LogFormat.yarp().read(missing, ignore).drain());
        assertThrows(NoSuchFileException.class, () -> LogFormat.yarp().follow(missing, ignore).drain());
    }
}
