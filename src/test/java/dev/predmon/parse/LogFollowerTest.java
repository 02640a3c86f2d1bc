package dev.predmon.parse;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class LogFollowerTest {

    @TempDir
    Path dir;

    /** Records lines and restarts in the order they arrive. */
    private static final class Events implements LineSink {
        final List<String> events = new ArrayList<>();

        @Override
        public void line(String line) {
            events.add(line);
        }

        @Override
        public void restarted(String reason) {
            events.add("<restarted " + reason + ">");
        }
    }

    @Test
    void appendsCutAnywhereGiveTheSameRecordsAsTheWholeFile() throws IOException {
        String log = SampleLogs.mixed(60, 11);
        Path file = dir.resolve("live.log");
        List<LogRecord> expected = new ArrayList<>();
        LogReader.read(Files.writeString(dir.resolve("whole.log"), log), expected::add, p -> { });

        Collected live = new Collected();
        Random random = new Random(5);
        byte[] bytes = log.getBytes(StandardCharsets.UTF_8);
        try (LogFollower follower = new LogFollower(file, live.parser.lineSink())) {
            assertFalse(follower.poll(), "no file yet");
            Files.createFile(file);
            for (int at = 0; at < bytes.length; ) {
                int n = Math.min(bytes.length - at, 1 + random.nextInt(40));
                append(file, bytes, at, n);
                at += n;
                follower.poll();
            }
            assertFalse(follower.poll(), "nothing new");
        }
        assertEquals(expected, live.records);
        assertEquals(List.of(), live.problems);
    }

    @Test
    void unterminatedLineIsHeldUntilItsNewline() throws IOException {
        Path file = Files.writeString(dir.resolve("a.log"), "one\ntw");
        Events sink = new Events();
        try (LogFollower follower = new LogFollower(file, sink)) {
            assertTrue(follower.poll());
            assertEquals(List.of("one"), sink.events);
            Files.writeString(file, "o\r\nthr", StandardOpenOption.APPEND);
            follower.poll();
            assertEquals(List.of("one", "two"), sink.events);
            follower.drainToEnd();
            assertEquals(List.of("one", "two", "thr"), sink.events);
        }
    }

    @Test
    void truncateAndRewriteRestartsFromTheBeginning() throws IOException {
        Path file = Files.writeString(dir.resolve("a.log"), "a1\na2\na3\n");
        Events sink = new Events();
        try (LogFollower follower = new LogFollower(file, sink)) {
            follower.poll();
            Files.writeString(file, "b1\n", StandardOpenOption.TRUNCATE_EXISTING);
            assertTrue(follower.poll());
            Files.writeString(file, "b2\n", StandardOpenOption.APPEND);
            follower.poll();
            assertFalse(follower.poll());
        }
        assertEquals(List.of("a1", "a2", "a3", "<restarted truncated>", "b1", "b2"), sink.events);
    }

    /** A follower that finishes a replaced file as soon as it is read to its end, and the new file has data. */
    private static LogFollower finishingAtOnce(Path file, LineSink sink) {
        return new LogFollower(file, sink, LineSplitter.DEFAULT_MAX_LINE_BYTES, 0, System::nanoTime);
    }

    @Test
    void renameAwayAndRecreateDrainsTheOldFileFirst() throws IOException {
        Path file = Files.writeString(dir.resolve("a.log"), "a1\n");
        Events sink = new Events();
        try (LogFollower follower = finishingAtOnce(file, sink)) {
            follower.poll();
            Files.writeString(file, "a2\na3", StandardOpenOption.APPEND);
            Files.move(file, dir.resolve("a.log.1"));
            Files.writeString(file, "b1\nb2\n");
            assertTrue(follower.poll());
            Files.writeString(file, "b3\n", StandardOpenOption.APPEND);
            follower.poll();
            // the old file's unterminated line is held: its writer completes it in the renamed file
            Files.writeString(dir.resolve("a.log.1"), " done\n", StandardOpenOption.APPEND);
            follower.poll();
        }
        assertEquals(List.of("a1", "a2", "<restarted replaced>", "b1", "b2", "b3", "a3 done"), sink.events);
    }

    /**
     * logrotate's default: the log is renamed and an empty one created, and the program writes on to the renamed file
     * until it reopens its log. Everything it writes there is read, before the new file, however long it goes on;
     * the new file is read once it holds something and the old one has been quiet for the quiet time, and what the
     * writer adds to the renamed file after that is read too.
     */
    @Test
    void aRenamedFileStillWrittenIsReadToItsEndBeforeTheNewOne() throws IOException {
        Path file = Files.writeString(dir.resolve("a.log"), "a1\n");
        Path rotated = dir.resolve("a.log.1");
        Events sink = new Events();
        long[] now = {0};
        long quiet = 1_000_000_000L;
        try (LogFollower follower = new LogFollower(file, sink, LineSplitter.DEFAULT_MAX_LINE_BYTES, quiet,
                () -> now[0])) {
            follower.poll();
            Files.move(file, rotated);
            Files.writeString(file, "");
            for (int i = 2; i <= 5; i++) { // the writer goes on with the renamed file, a record every 0.4 s
                now[0] += 400_000_000L;
                Files.writeString(rotated, "a" + i + "\n", StandardOpenOption.APPEND);
                follower.poll();
            }
            now[0] += 5 * quiet;
            assertFalse(follower.poll(), "quiet, but the new file is empty: nothing to read there yet");
            Files.writeString(rotated, "a6 warning\n", StandardOpenOption.APPEND); // the writer is not done after all
            Files.writeString(file, "b1\n"); // and another writer begins the new file
            follower.poll();
            assertEquals(List.of("a1", "a2", "a3", "a4", "a5", "a6 warning"), sink.events, "the old file first");
            now[0] += quiet - 1;
            follower.poll();
            assertEquals(6, sink.events.size(), "not quiet for long enough yet");
            now[0] += 1;
            assertTrue(follower.poll());
            Files.writeString(rotated, "a7 after the turn\n", StandardOpenOption.APPEND); // read on after the turn
            follower.poll();
        }
        assertEquals(List.of("a1", "a2", "a3", "a4", "a5", "a6 warning", "<restarted replaced>", "b1",
                "a7 after the turn"), sink.events);
    }

    /** Rotated again before the old file was done: each new file is held open and read in its turn, none lost. */
    @Test
    void filesRotatedAgainWhileTheOldOneIsWrittenAreReadInTurn() throws IOException {
        Path file = Files.writeString(dir.resolve("a.log"), "a1\n");
        Events sink = new Events();
        long[] now = {0};
        try (LogFollower follower = new LogFollower(file, sink, LineSplitter.DEFAULT_MAX_LINE_BYTES, 10, () -> now[0])) {
            follower.poll();
            Files.move(file, dir.resolve("a.log.1"));
            Files.writeString(file, "b1\n");
            Files.writeString(dir.resolve("a.log.1"), "a2\n", StandardOpenOption.APPEND);
            follower.poll();
            Files.move(file, dir.resolve("a.log.2"));
            Files.writeString(file, "c1\n");
            follower.poll();
            Files.delete(dir.resolve("a.log.2"));
            now[0] += 10;
            follower.poll();
            now[0] += 10;
            follower.poll();
        }
        assertEquals(List.of("a1", "a2", "<restarted replaced>", "b1", "<restarted replaced>", "c1"), sink.events);
    }

    @Test
    void deletedFileIsDrainedThenANewOneIsWaitedFor() throws IOException {
        Path file = Files.writeString(dir.resolve("a.log"), "a1\n");
        Events sink = new Events();
        try (LogFollower follower = finishingAtOnce(file, sink)) {
            follower.poll();
            Files.writeString(file, "a2\n", StandardOpenOption.APPEND);
            Files.delete(file);
            assertTrue(follower.poll(), "the old handle still has a2");
            assertFalse(follower.poll());
            Files.writeString(file, "b1\n");
            assertTrue(follower.poll());
        }
        assertEquals(List.of("a1", "a2", "<restarted replaced>", "b1"), sink.events);
    }

    @Test
    void fileCreatedLaterIsPickedUpWithoutARestart() throws IOException {
        Path file = dir.resolve("later.log");
        Collected live = new Collected();
        try (LogFollower follower = new LogFollower(file, live.parser.lineSink())) {
            assertFalse(follower.poll());
            assertFalse(follower.poll());
            Files.writeString(file, SampleLogs.mixed(3, 4));
            assertTrue(follower.poll());
        }
        assertEquals(3, live.records.size());
        assertEquals(List.of(), live.problems);
    }

    @Test
    void rotationMidRecordWarnsAndTheNewFileParses() throws IOException {
        String log = SampleLogs.mixed(2, 9);
        String[] lines = log.split("(?<=\n)", -1);
        Path file = Files.writeString(dir.resolve("a.log"), lines[0] + lines[1] + lines[2]);
        Collected live = new Collected();
        try (LogFollower follower = finishingAtOnce(file, live.parser.lineSink())) {
            follower.poll();
            Files.move(file, dir.resolve("a.log.1"));
            Files.writeString(file, log);
            follower.poll();
        }
        assertEquals(2, live.records.size());
        assertEquals(1, live.problems.size());
        assertEquals(ParseProblem.Severity.WARNING, live.problems.get(0).severity());
        assertEquals(2, live.problems.get(0).line());
    }

    @Test
    void overlongLineIsSkippedAndCountedAsOneLine() throws IOException {
        Path file = Files.writeString(dir.resolve("a.log"), "a\n" + "x".repeat(100) + "\nb\n");
        Events sink = new Events();
        try (LogFollower follower = new LogFollower(file, sink, 10)) {
            follower.poll();
        }
        assertEquals(List.of("a", "", "b"), sink.events);
    }

    @Test
    void drainToEndOfAMissingFileFails() {
        LogFollower follower = new LogFollower(dir.resolve("absent.log"), new Events());
        assertThrows(NoSuchFileException.class, follower::drainToEnd);
    }

    private static void append(Path file, byte[] bytes, int offset, int length) throws IOException {
        try (var out = Files.newOutputStream(file, StandardOpenOption.APPEND)) {
            out.write(bytes, offset, length);
        }
    }
}
