package dev.predmon.parse;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * {@link LogFollower} where rotation leaves something other than one written file after another: empty files in the
 * chain (rotated twice before the logger reopened, or an empty file rotated in and deleted), a FIFO or a directory
 * at the path, a file closed to spare a descriptor, a deleted file no one writes any more. The clock is the test's.
 */
class FollowerChainTest {

    private static final long QUIET = 1_000_000_000L;
    private static final long RELEASE = 60_000_000_000L;

    @TempDir
    Path dir;

    private final long[] now = {0};
    private final List<String> events = new ArrayList<>();

    private LogFollower follower(Path file) {
        return new LogFollower(file, new LineSink() {
            @Override
            public void line(String line) {
                events.add(line);
            }

            @Override
            public void restarted(String reason) {
                events.add("<restarted " + reason + ">");
            }
        }, LineSplitter.DEFAULT_MAX_LINE_BYTES, QUIET, RELEASE, () -> now[0]);
    }

    /**
     * {@code exec 3>>live.log; mv live.log live.log.1; : >live.log; mv live.log live.log.2; : >live.log; cat dep.log
     * >>live.log}: the middle file never gets a byte, and the file now at the path is read once the first is quiet.
     */
    @Test
    void twoRenamesBeforeTheLoggerReopensDoNotStallOnTheEmptyMiddleFile() throws IOException {
        Path file = Files.writeString(dir.resolve("live.log"), "a1\n");
        try (LogFollower f = follower(file); OutputStream logger = Files.newOutputStream(file, StandardOpenOption.APPEND)) {
            f.poll();
            Files.move(file, dir.resolve("live.log.1"));
            Files.writeString(file, "");
            f.poll();
            Files.move(file, dir.resolve("live.log.2"));
            Files.writeString(file, "");
            f.poll();
            Files.writeString(file, "c1\nc2\n", StandardOpenOption.APPEND);
            f.poll();
            now[0] += QUIET;
            assertTrue(f.poll());
            Files.writeString(file, "c3\n", StandardOpenOption.APPEND);
            f.poll();
            assertEquals(2, f.openFiles(), "the empty files passed over are closed; the first is kept a while");
            logger.write("a2\n".getBytes(StandardCharsets.UTF_8)); // the first logger's handle is still open: read on
            logger.flush();
            f.poll();
        }
        assertEquals(List.of("a1", "<restarted replaced>", "c1", "c2", "c3", "a2"), events);
    }

    /** An empty file rotated in, then deleted before anything was written to it, and a new file at the path. */
    @Test
    void anEmptyFileRotatedInAndDeletedDoesNotStall() throws IOException {
        Path file = Files.writeString(dir.resolve("live.log"), "a1\n");
        try (LogFollower f = follower(file)) {
            f.poll();
            Files.move(file, dir.resolve("live.log.1"));
            Files.writeString(file, "");
            f.poll();
            Files.delete(file);
            f.poll();
            Files.writeString(file, "b1\n");
            f.poll();
            now[0] += QUIET;
            f.poll();
        }
        assertEquals(List.of("a1", "<restarted replaced>", "b1"), events);
    }

    /** A FIFO put at the path is never opened (opening it would block until a writer comes); a file after it is read. */
    @Test
    @Timeout(20)
    void aFifoAtThePathIsNeverOpened() throws Exception {
        Path file = Files.writeString(dir.resolve("live.log"), "a1\n");
        try (LogFollower f = follower(file)) {
            f.poll();
            Files.delete(file);
            assumeTrue(mkfifo(file), "no mkfifo here");
            assertFalse(f.poll(), "nothing new, and no wait for a writer of the FIFO");
            assertEquals(Optional.of("is a FIFO, not a regular file"), f.obstacle());
            now[0] += QUIET;
            assertFalse(f.poll());
            Files.delete(file);
            Files.writeString(file, "b1\n");
            f.poll();
            now[0] += QUIET;
            f.poll();
            assertEquals(Optional.empty(), f.obstacle());
        }
        assertEquals(List.of("a1", "<restarted replaced>", "b1"), events);
    }

    /** A directory at the path is not read as a log ("is a directory" was an I/O error that ended watch). */
    @Test
    void aDirectoryAtThePathIsNoError() throws IOException {
        Path file = Files.writeString(dir.resolve("live.log"), "a1\n");
        try (LogFollower f = follower(file)) {
            f.poll();
            Files.delete(file);
            Files.createDirectory(file);
            now[0] += QUIET;
            assertFalse(f.poll());
            assertEquals(Optional.of("is a directory, not a regular file"), f.obstacle());
        }
        assertEquals(List.of("a1"), events);
    }

    /** A file closed to spare a descriptor is not reopened while unchanged, and is read on where it stopped. */
    @Test
    void aReleasedFileIsReopenedWhereReadingStoppedOnceItChanged() throws IOException {
        Path file = Files.writeString(dir.resolve("live.log"), "a1\na");
        try (LogFollower f = follower(file)) {
            f.poll();
            assertTrue(f.release());
            assertEquals(0, f.openFiles());
            assertFalse(f.poll());
            assertEquals(0, f.openFiles(), "unchanged: not opened");
            Files.writeString(file, "2\na3\n", StandardOpenOption.APPEND);
            assertTrue(f.poll());
            assertEquals(1, f.openFiles());
            f.release();
            Files.move(file, dir.resolve("live.log.1"));
            Files.writeString(file, "b1\n");
            assertTrue(f.poll());
        }
        assertEquals(List.of("a1", "a2", "a3", "<restarted replaced>", "b1"), events);
    }

    /** A deleted file is drained, then closed once quiet for the release time; a new file at the path is read. */
    @Test
    void aDeletedFileIsClosedOnceQuietAndANewOneReadAfter() throws IOException {
        Path file = Files.writeString(dir.resolve("live.log"), "a1\n");
        try (LogFollower f = follower(file)) {
            f.poll();
            Files.delete(file);
            now[0] += RELEASE - 1;
            f.poll();
            assertEquals(1, f.openFiles(), "a writer may still hold it");
            now[0] += 1;
            f.poll();
            assertEquals(0, f.openFiles(), "quiet for the release time: closed");
            Files.writeString(file, "b1\n");
            assertTrue(f.poll());
        }
        assertEquals(List.of("a1", "<restarted replaced>", "b1"), events);
    }

    /**
     * A logger that pauses after a rename rotation for longer than the quiet time, then goes on writing to the renamed
     * file after the follower took up the new one: what it writes there is read, for as long as it grows, and
     * the renamed file is let go once it has not grown for the release time (its unterminated last line delivered).
     */
    @Test
    void aRenamedFileWrittenAgainAfterTheTurnIsReadOnAndLetGoOnceQuiet() throws IOException {
        Path file = Files.writeString(dir.resolve("live.log"), "a1\n");
        Path rotated = dir.resolve("live.log.1");
        try (LogFollower f = follower(file)) {
            f.poll();
            Files.move(file, rotated);
            Files.writeString(file, "b1\n");
            f.poll();
            now[0] += QUIET;
            f.poll();
            assertEquals(List.of("a1", "<restarted replaced>", "b1"), events);
            assertEquals(2, f.openFiles(), "the renamed file is kept open");
            assertTrue(f.readingRenamed());
            Files.writeString(rotated, "a2 warning\n", StandardOpenOption.APPEND);
            Files.writeString(file, "b2\n", StandardOpenOption.APPEND);
            assertTrue(f.poll());
            assertEquals(List.of("a1", "<restarted replaced>", "b1", "a2 warning", "b2"), events,
                    "the renamed file is read before the file at the path");
            now[0] += RELEASE - 1;
            Files.writeString(rotated, "a3", StandardOpenOption.APPEND); // grows again: kept on
            f.poll();
            now[0] += RELEASE - 1;
            f.poll();
            assertEquals(2, f.openFiles(), "grew less than the release time ago");
            now[0] += 1;
            f.poll();
            assertEquals(1, f.openFiles(), "quiet for the release time: let go");
            assertFalse(f.readingRenamed());
        }
        assertEquals(List.of("a1", "<restarted replaced>", "b1", "a2 warning", "b2", "a3"), events,
                "its unterminated last line delivered when it is let go");
    }

    /**
     * With a sink per file, a line cut where the old writer paused is completed by its next write to the renamed file,
     * whatever the new file holds meanwhile; each sink hears {@code ended()} when its file is done with.
     */
    @Test
    void eachFileHasItsOwnPartialLineAndSink() throws IOException {
        Path file = Files.writeString(dir.resolve("live.log"), "a1\na2 cut ");
        Path rotated = dir.resolve("live.log.1");
        List<List<String>> perFile = new ArrayList<>();
        try (LogFollower f = new LogFollower(file, () -> {
            List<String> mine = new ArrayList<>();
            perFile.add(mine);
            return new LineSink() {
                @Override
                public void line(String line) {
                    mine.add(line);
                }

                @Override
                public void restarted(String reason) {
                    mine.add("<" + reason + ">");
                }

                @Override
                public void ended() {
                    mine.add("<ended>");
                }
            };
        }, LineSplitter.DEFAULT_MAX_LINE_BYTES, QUIET, RELEASE, () -> now[0])) {
            f.poll();
            Files.move(file, rotated);
            Files.writeString(file, "b1 partial");
            f.poll();
            now[0] += QUIET;
            f.poll();
            Files.writeString(rotated, "in two\na3\n", StandardOpenOption.APPEND);
            Files.writeString(file, " line\n", StandardOpenOption.APPEND);
            f.poll();
            assertEquals(List.of(List.of("a1", "a2 cut in two", "a3"), List.of("<replaced>", "b1 partial line")),
                    perFile);
            Files.delete(rotated);
            f.poll();
            assertFalse(f.readingRenamed(), "a renamed file that is deleted is let go at once");
            assertEquals(1, f.openFiles());
        }
        assertEquals(List.of("a1", "a2 cut in two", "a3", "<ended>"), perFile.get(0));
    }

    /** A renamed file renamed again by a later rotation is found again, and read on; deleted, it is let go. */
    @Test
    void aRenamedFileRenamedAgainIsReadOnThenLetGoWhenDeleted() throws IOException {
        Path file = Files.writeString(dir.resolve("live.log"), "a1\n");
        try (LogFollower f = follower(file); OutputStream logger = Files.newOutputStream(file, StandardOpenOption.APPEND)) {
            f.poll();
            Files.move(file, dir.resolve("live.log.1"));
            Files.writeString(file, "b1\n");
            f.poll();
            now[0] += QUIET;
            f.poll();
            Files.move(dir.resolve("live.log.1"), dir.resolve("live.log.2"));
            logger.write("a2\n".getBytes(StandardCharsets.UTF_8));
            logger.flush();
            f.poll();
            assertTrue(f.readingRenamed(), "found again under its new name");
            Files.delete(dir.resolve("live.log.2"));
            f.poll();
            assertFalse(f.readingRenamed(), "deleted: let go");
        }
        assertEquals(List.of("a1", "<restarted replaced>", "b1", "a2"), events);
    }

    static boolean mkfifo(Path path) throws InterruptedException {
        try {
            return new ProcessBuilder("mkfifo", path.toString()).inheritIO().start().waitFor() == 0;
        } catch (IOException e) {
            return false;
        }
    }
}
