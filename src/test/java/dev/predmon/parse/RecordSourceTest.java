package dev.predmon.parse;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

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

    /**
     * The order rule of a followed log across a rename rotation: the new run begins at the new file's first record
     * (its other lines begin none), what the old writer adds to the renamed file before that continues the old run,
     * and a record of the renamed file after the new file gave one goes into the run under way, told once.
     */
    @Test
    void aRotationsRunBeginsAtTheNewFilesFirstRecordAndTwoWritersAreToldOf() throws Exception {
        Path log = Files.writeString(dir.resolve("live.log"), record(1));
        List<String> events = new ArrayList<>();
        RecordSink sink = new RecordSink() {
            @Override
            public void record(LogRecord r) {
                events.add(r.command() + "@" + r.line());
            }

            @Override
            public void problem(ParseProblem p) {
                events.add("problem " + p);
            }

            @Override
            public void restarted(String reason) {
                events.add("<" + reason + ">");
            }
        };
        try (RecordSource s = LogFormat.yarp().follow(log, sink, Duration.ofMillis(20), Duration.ofSeconds(60));
             OutputStream old = Files.newOutputStream(log, StandardOpenOption.APPEND)) {
            s.poll();
            Files.move(log, dir.resolve("live.log.1"));
            Files.writeString(log, "yarprun: starting\n");
            s.poll();
            Thread.sleep(60);
            s.poll();
            assertTrue(s.readingRenamed());
            old.write(record(2).getBytes(StandardCharsets.UTF_8));
            old.flush();
            s.poll();
            assertEquals(List.of("c1@1", "c2@8"), events, "the old run goes on; another program's line begins none");
            Files.writeString(log, record(3), StandardOpenOption.APPEND);
            s.poll();
            assertEquals(Optional.empty(), s.takeNotice());
            old.write(record(4).getBytes(StandardCharsets.UTF_8));
            old.flush();
            s.poll();
            assertEquals(List.of("c1@1", "c2@8", "<replaced>", "c3@2", "c4@15"), events);
            assertTrue(s.takeNotice().orElseThrow().contains("two writers"));
            assertEquals(Optional.empty(), s.takeNotice(), "told once");
        }
    }

    /** One complete record in the column layout, command {@code c<n>}. */
    private static String record(int n) {
        return n + ".0\tDEBUG\tCommand intercepted:\n  From      : /a\n  To        : /b\n  Protocol  : P\n"
                + "  Command   : c" + n + "\n  Arguments : \n  Reply     : \n";
    }

    @Test
    void aMissingLogIsAnErrorBothWays() {
        Path missing = dir.resolve("missing.log");
        RecordSink ignore = RecordSink.of(r -> { }, p -> { });
        assertThrows(NoSuchFileException.class, () -> LogFormat.yarp().read(missing, ignore).drain());
        assertThrows(NoSuchFileException.class, () -> LogFormat.yarp().follow(missing, ignore).drain());
    }
}
