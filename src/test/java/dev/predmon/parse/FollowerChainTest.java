package dev.predmon.parse;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.OutputStream;
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
            logger.write('x'); // the first logger's handle is still open: what it writes now is told, not read
            logger.flush();
            f.poll();
            assertTrue(f.takeNotice().isPresent());
        }
        assertEquals(List.of("a1", "<restarted replaced>", "c1", "c2", "c3"), events);
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
     * file after the follower took up the new one: what it writes there is not read, and the follower says so once,
     * instead of losing it silently. A renamed file that stays quiet is closed after the release time.
     */
    @Test
    void aRenamedFileWrittenAgainAfterTheTurnIsToldOfOnce() throws IOException {
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
            assertEquals(2, f.openFiles(), "the renamed file is kept open a while");
            assertEquals(Optional.empty(), f.takeNotice());
            Files.writeString(rotated, "a2 warning\n", StandardOpenOption.APPEND);
            f.poll();
            assertEquals(Optional.of("the file renamed away at the last rotation grew by 11 bytes after the file now "
                    + "at the path was taken up: a writer went on in it, and what it wrote there is not read"),
                    f.takeNotice());
            assertEquals(Optional.empty(), f.takeNotice(), "said once");
            assertEquals(1, f.openFiles());

            Files.move(file, dir.resolve("live.log.2"));
            Files.writeString(file, "c1\n");
            f.poll();
            now[0] += QUIET;
            f.poll();
            assertEquals(2, f.openFiles());
            now[0] += RELEASE;
            f.poll();
            assertEquals(1, f.openFiles(), "quiet for the release time: closed");
            assertEquals(Optional.empty(), f.takeNotice());
        }
    }

    static boolean mkfifo(Path path) throws InterruptedException {
        try {
            return new ProcessBuilder("mkfifo", path.toString()).inheritIO().start().waitFor() == 0;
        } catch (IOException e) {
            return false;
        }
    }
}
