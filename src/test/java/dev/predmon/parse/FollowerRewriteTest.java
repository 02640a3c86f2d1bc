package dev.predmon.parse;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** Copytruncate races that {@code tail -F} misses and {@link LogFollower} must not: no line skipped. */
class FollowerRewriteTest {

    @TempDir
    Path dir;

    private final List<String> events = new ArrayList<>();
    private final LineSink sink = new LineSink() {
        @Override
        public void line(String line) {
            events.add(line);
        }

        @Override
        public void restarted(String reason) {
            events.add("<" + reason + ">");
        }
    };

    private static void truncate(Path file) throws IOException {
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.WRITE)) {
            ch.truncate(0);
        }
    }

    @Test
    void truncatedAndRewrittenPastTheReadPositionBetweenTwoPolls() throws IOException {
        Path log = Files.writeString(dir.resolve("a.log"), "old 1\nold 2\n");
        try (LogFollower f = new LogFollower(log, sink)) {
            f.poll();
            truncate(log);
            Files.writeString(log, "new 1\nnew 2\nnew 3\n", StandardOpenOption.APPEND);
            f.poll();
        }
        assertEquals(List.of("old 1", "old 2", "<truncated>", "new 1", "new 2", "new 3"), events);
    }

    @Test
    void aPollAfterAWriteAloneStillSeesATruncationAndRewrite() throws IOException {
        Path log = Files.writeString(dir.resolve("a.log"), "old 1\nold 2\n");
        try (LogFollower f = new LogFollower(log, sink)) {
            f.poll();
            Files.writeString(log, "old 3\n", StandardOpenOption.APPEND);
            f.pollWritten();
            truncate(log);
            Files.writeString(log, "new 1\nnew 2\nnew 3\nnew 4\n", StandardOpenOption.APPEND);
            f.pollWritten();
        }
        assertEquals(List.of("old 1", "old 2", "old 3", "<truncated>", "new 1", "new 2", "new 3", "new 4"), events);
    }

    @Test
    void aPollAfterAWriteAloneReadsPastOneBufferAndLeavesTheLookAtThePathToAFullPoll() throws IOException {
        Path log = Files.writeString(dir.resolve("a.log"), "first\n");
        StringBuilder big = new StringBuilder();
        for (int i = 0; i < 20_000; i++) { // about 200 KB: several reads of the 64 KiB buffer
            big.append("line ").append(i).append('\n');
        }
        try (LogFollower f = new LogFollower(log, sink, LineSplitter.DEFAULT_MAX_LINE_BYTES, 0, System::nanoTime)) {
            f.poll();
            Files.writeString(log, big, StandardOpenOption.APPEND);
            f.pollWritten();
            assertEquals(20_001, events.size());
            assertEquals("line 19999", events.get(events.size() - 1));
            Files.delete(log);
            Files.writeString(log, "other 1\n");
            f.pollWritten(); // a write was all it was told: the new file at the path is not looked for
            assertEquals(20_001, events.size());
            f.poll();
        }
        assertEquals(List.of("line 19999", "<replaced>", "other 1"), events.subList(20_000, events.size()));
    }

    @Test
    void truncatedRewrittenAndDeletedBetweenTwoPolls() throws IOException {
        Path log = Files.writeString(dir.resolve("a.log"), "old 1\nold 2\nold 3\n");
        // finishing a replaced file as soon as it is read: the race is the point here, not a writer still at it
        try (LogFollower f = new LogFollower(log, sink, LineSplitter.DEFAULT_MAX_LINE_BYTES, 0, System::nanoTime)) {
            f.poll();
            truncate(log);
            Files.writeString(log, "mid 1\n", StandardOpenOption.APPEND);
            Files.delete(log);
            Files.writeString(log, "new 1\n");
            f.poll();
        }
        assertEquals(List.of("old 1", "old 2", "old 3", "<truncated>", "mid 1", "<replaced>", "new 1"), events);
    }
}
