package dev.predmon.files;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@link AtomicFiles}: a write that fails part-way leaves the previous file exactly as it was and nothing beside
 * it, and says so in one line naming the file. What a full disk does to a real process is checked end to end in
 * {@code FileSizeLimitTest}; here the failure comes from the writer itself, after part of the text went out.
 */
class AtomicFilesTest {

    @TempDir
    Path tmp;

    @Test
    void aWriteThatFailsPartWayLeavesThePreviousFileAndNothingElse() throws Exception {
        Path file = Files.writeString(tmp.resolve("report.html"), "the previous report\n");
        FileSystemException e = assertThrows(FileSystemException.class, () -> AtomicFiles.replace(file, out -> {
            out.write("x".repeat(1 << 20)); // more than the buffer: part of it reaches the file before the failure
            throw new IOException("No space left on device");
        }));
        assertEquals(file + ": not written (no space left on device); the previous file is unchanged", e.getMessage());
        assertEquals("the previous report\n", Files.readString(file));
        assertEquals(List.of(file), list(tmp), "no temporary file is left");
    }

    @Test
    void aNewFileThatFailsIsNotLeftHalfWritten() {
        Path file = tmp.resolve("samples.txt");
        FileSystemException e = assertThrows(FileSystemException.class, () -> AtomicFiles.replace(file, out -> {
            out.write("# predmon Mealy samples\n");
            throw new IOException("File too large");
        }));
        assertEquals(file + ": not written (file too large); no partial file was left", e.getMessage());
        assertFalse(Files.exists(file));
        assertEquals(List.of(), list(tmp));
    }

    @Test
    void aCompleteWriteReplacesTheFileAndKeepsItsPermissions() throws Exception {
        Path file = Files.writeString(tmp.resolve("run.log"), "old\n");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r-----"));
        AtomicFiles.replace(file, "new ".repeat(100_000));
        assertEquals("new ".repeat(100_000), Files.readString(file));
        assertEquals("rw-r-----", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
        assertEquals(List.of(file), list(tmp));
    }

    /** A link is followed: the file it points to is replaced and the link stays a link. */
    @Test
    void aLinkIsFollowed() throws Exception {
        Path target = Files.writeString(Files.createDirectories(tmp.resolve("reports")).resolve("r.html"), "old");
        Path link = Files.createSymbolicLink(tmp.resolve("latest.html"), target);
        AtomicFiles.replace(link, "new");
        assertTrue(Files.isSymbolicLink(link));
        assertEquals("new", Files.readString(target));
    }

    /** What a killed write left (a hidden temporary file of a process that is gone) goes with the next write. */
    @Test
    void theTemporaryFileOfAKilledWriteIsRemovedByTheNext() throws Exception {
        Path file = Files.writeString(tmp.resolve("index.json"), "{}");
        Path abandoned = Files.writeString(tmp.resolve(".index.json." + deadPid() + "-42.tmp"), "{\"for");
        Path usersOwn = Files.writeString(tmp.resolve(".index.json.backup.tmp"), "mine");
        AtomicFiles.replace(file, "{\"format\": 1}");
        assertFalse(Files.exists(abandoned));
        assertEquals("mine", Files.readString(usersOwn));
    }

    @Test
    void aFileInADirectoryThatCannotBeWrittenIsNamed() throws Exception {
        Path file = tmp.resolve("missing-dir").resolve("report.html");
        FileSystemException e = assertThrows(FileSystemException.class, () -> AtomicFiles.replace(file, "x"));
        assertEquals(file + ": not written (no such file); no partial file was left", e.getMessage());
    }

    @Test
    void createWritesANewFileAndNeverAnExistingOne() throws Exception {
        Path file = tmp.resolve("a.dot");
        AtomicFiles.create(file, "digraph g {}\n");
        assertEquals("digraph g {}\n", Files.readString(file));
        assertThrows(FileAlreadyExistsException.class, () -> AtomicFiles.create(file, "other"));
        assertEquals("digraph g {}\n", Files.readString(file), "an existing file is not touched");
    }

    /** The pid of a process that has ended. */
    private static long deadPid() throws Exception {
        Process p = new ProcessBuilder("true").start();
        p.waitFor();
        return p.pid();
    }

    private static List<Path> list(Path dir) {
        try (Stream<Path> s = Files.list(dir)) {
            return s.sorted().toList();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }
}
