package dev.predmon.files;

import dev.predmon.BadInputException;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ThreadLocalRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Writes a file completely or not at all: every file predmon writes (models, reports, samples, simulated logs)
 * goes through here, so that a full disk or a file-size limit never leaves a truncated file in place of a good one.
 *
 * <p>{@link #replace} writes the whole text to a hidden temporary file in the target's directory, checks that
 * every byte was taken (a write may take fewer bytes than it was given, and a full disk or {@code ulimit -f}
 * shows first as such a short write), forces it to the disk, and only then renames it over the target in one
 * atomic step, then forces the directory. Until that rename the previous file is untouched; after it the new file
 * is there in full. A failure removes the temporary file and is reported as one line naming the target
 * ({@link #notWritten}). A process killed mid-write leaves at most its hidden temporary file, which the next
 * replace of the same file removes.
 *
 * <p>{@link #create} does the same checks for a new file in a directory that is itself moved into place later
 * (the staging directory of a model directory), where a rename per file would add nothing.
 */
public final class AtomicFiles {

    /** What writes a file's text; called once, with a buffered writer that encodes UTF-8. */
    @FunctionalInterface
    public interface Body {
        void writeTo(Writer out) throws IOException;
    }

    private AtomicFiles() {
    }

    /** Replaces {@code file} with {@code text} (UTF-8), completely or not at all. */
    public static void replace(Path file, String text) throws IOException {
        replace(file, out -> out.write(text));
    }

    /**
     * Replaces {@code file} with what {@code body} writes (UTF-8), completely or not at all. A link is followed:
     * the file it points to is replaced, and an existing file keeps its permissions.
     *
     * @throws FileSystemException naming {@code file} when anything fails; the previous file is then unchanged
     */
    public static void replace(Path file, Body body) throws IOException {
        Staged staged = stage(file, body, "the previous file is unchanged");
        try {
            staged.moveIn();
        } catch (IOException e) {
            throw staged.failed(e, "the previous file is unchanged");
        }
    }

    /**
     * Replaces {@code first} and then {@code second} (a log and its sidecar), each completely or not at all, as
     * nearly as a pair as files allow: both are written and forced before either is renamed into place, so a full
     * disk, a file-size limit or any other failure to write leaves both previous files as they were. Only a process
     * killed between the two renames, microseconds apart, leaves the new {@code first} beside the previous
     * {@code second}.
     *
     * @throws FileSystemException naming the file that failed, saying what the user still has
     */
    public static void replaceBoth(Path first, Body firstBody, Path second, Body secondBody) throws IOException {
        String bothKept = "the previous " + first.getFileName() + " and " + second.getFileName() + " are unchanged";
        Staged a = stage(first, firstBody, bothKept);
        Staged b;
        try {
            b = stage(second, secondBody, bothKept);
        } catch (IOException | RuntimeException e) {
            a.discard();
            throw e;
        }
        try {
            a.moveIn();
        } catch (IOException e) {
            b.discard();
            throw a.failed(e, bothKept);
        }
        try {
            b.moveIn();
        } catch (IOException e) {
            throw b.failed(e, first.getFileName() + " is new, " + second.getFileName() + " is the previous one");
        }
    }

    /** A file written in full to its hidden temporary name, not yet renamed over its target. */
    private static final class Staged {
        private final Path shown;
        private final Path target;
        private final boolean existed;
        private Path temp;

        Staged(Path shown, Path target, boolean existed, Path temp) {
            this.shown = shown;
            this.target = target;
            this.existed = existed;
            this.temp = temp;
        }

        /** Renames the temporary file over the target and forces the directory. */
        void moveIn() throws IOException {
            Files.move(temp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            temp = null;
            forceDirectory(target.getParent());
        }

        /** Removes the temporary file, if it is still there. */
        void discard() throws IOException {
            if (temp != null) {
                Files.deleteIfExists(temp);
                temp = null;
            }
        }

        /** Discards, and the one-line failure naming the file ({@code kept} when the target existed). */
        FileSystemException failed(IOException e, String kept) throws IOException {
            discard();
            return notWritten(shown, e, existed ? kept : "no partial file was left");
        }
    }

    /**
     * Writes what {@code body} writes to a hidden temporary file beside {@code file}, checked and forced, with the
     * permissions of the file it will replace.
     *
     * @throws FileSystemException naming {@code file} when anything fails, with {@code kept} when it existed;
     *                             nothing is left behind
     */
    private static Staged stage(Path file, Body body, String kept) throws IOException {
        Path target = Files.exists(file) ? file.toRealPath() : file.toAbsolutePath();
        Path dir = target.getParent();
        removeAbandoned(dir, target.getFileName().toString());
        boolean existed = Files.exists(target);
        Path temp = null;
        try {
            temp = tempName(dir, target.getFileName().toString());
            writeNew(temp, body);
            if (existed) {
                copyPermissions(target, temp);
            }
            return new Staged(file, target, existed, temp);
        } catch (IOException | RuntimeException e) {
            if (temp != null) {
                Files.deleteIfExists(temp);
            }
            if (e instanceof IOException io) {
                throw notWritten(file, io, existed ? kept : "no partial file was left");
            }
            throw e;
        }
    }

    /**
     * Writes {@code text} (UTF-8) to the new file {@code file}, completely, and forces it to the disk; on failure
     * the partial file is removed and the {@link IOException} passed on for the caller to report.
     *
     * @throws FileAlreadyExistsException if {@code file} exists
     */
    public static void create(Path file, String text) throws IOException {
        try {
            writeNew(file, out -> out.write(text));
        } catch (FileAlreadyExistsException e) {
            throw e; // not ours to delete
        } catch (IOException | RuntimeException e) {
            Files.deleteIfExists(file);
            throw e;
        }
    }

    /**
     * The one-line failure of a write: {@code FILE: not written (REASON); KEPT}, as a {@link FileSystemException}
     * naming {@code shown}, the file as the user named it.
     *
     * @param kept what the user still has, e.g. "the previous file is unchanged"
     */
    public static FileSystemException notWritten(Path shown, IOException cause, String kept) {
        FileSystemException e = new FileSystemException(shown.toString(), null,
                "not written (" + BadInputException.reason(cause) + "); " + kept);
        e.initCause(cause);
        return e;
    }

    /**
     * The one-line failure of a file that is written in place as it grows, because a monitor tails it (a live
     * simulated log): {@code FILE: writing stopped (REASON); it holds the records written before}.
     */
    public static FileSystemException stoppedInPlace(Path shown, IOException cause) {
        FileSystemException e = new FileSystemException(shown.toString(), null,
                "writing stopped (" + BadInputException.reason(cause) + "); it holds the records written before");
        e.initCause(cause);
        return e;
    }

    /** Creates {@code file}, which must not exist, writes {@code body} into it, checks its size and forces it. */
    private static void writeNew(Path file, Body body) throws IOException {
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE)) {
            CheckedSink sink = new CheckedSink(ch);
            try (Writer out = new BufferedWriter(new OutputStreamWriter(sink, StandardCharsets.UTF_8), 1 << 16)) {
                body.writeTo(out);
            }
            // The channel's own count against what was handed to it: a file system that dropped bytes silently
            // would otherwise pass for complete.
            if (ch.size() != sink.written) {
                throw new IOException("only " + ch.size() + " of " + sink.written + " bytes reached the file");
            }
            // Written is not stored: without this the rename could reach the disk before the data.
            ch.force(true);
        }
    }

    /**
     * The bytes of a file channel, each write taken in full or failed: {@link FileChannel#write} may write fewer
     * bytes than asked and report it only in its return value (a file-size limit, a full disk), and the JDK's
     * {@code Channels.newOutputStream} answers a write of zero bytes with an unchecked exception.
     */
    private static final class CheckedSink extends OutputStream {
        private final FileChannel ch;
        long written;

        CheckedSink(FileChannel ch) {
            this.ch = ch;
        }

        @Override
        public void write(int b) throws IOException {
            write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            ByteBuffer buf = ByteBuffer.wrap(b, off, len);
            while (buf.hasRemaining()) {
                if (ch.write(buf) <= 0) {
                    throw new IOException("no space left: the file system took no more bytes");
                }
            }
            written += len;
        }
    }

    /** A fresh hidden name beside the target, marked with this process's id for {@link #removeAbandoned}. */
    private static Path tempName(Path dir, String name) {
        while (true) {
            Path p = dir.resolve("." + name + "." + ProcessHandle.current().pid() + "-"
                    + ThreadLocalRandom.current().nextLong(Long.MAX_VALUE) + ".tmp");
            if (!Files.exists(p, LinkOption.NOFOLLOW_LINKS)) {
                return p; // created by writeNew with CREATE_NEW: a name taken meanwhile fails there, never overwrites
            }
        }
    }

    /** Removes the temporary files of {@code name} left by replaces whose process is gone (killed mid-write). */
    private static void removeAbandoned(Path dir, String name) {
        Pattern own = Pattern.compile("\\." + Pattern.quote(name) + "\\.(\\d{1,19})-\\d{1,19}\\.tmp");
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : s.toList()) {
                Matcher m = own.matcher(p.getFileName().toString());
                if (m.matches() && !alive(m.group(1)) && Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                    Files.deleteIfExists(p);
                }
            }
        } catch (IOException e) {
            // Nothing depends on it: the write itself reports a directory that cannot be used.
        }
    }

    private static boolean alive(String pid) {
        try {
            return ProcessHandle.of(Long.parseLong(pid)).map(ProcessHandle::isAlive).orElse(false);
        } catch (NumberFormatException e) {
            return true; // not a pid this class wrote: leave it
        }
    }

    private static void copyPermissions(Path from, Path to) throws IOException {
        try {
            Files.setPosixFilePermissions(to, Files.getPosixFilePermissions(from));
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system: the new file keeps the defaults
        }
    }

    /** Forces a directory, so that the rename is stored too; file systems that cannot do this are left as they are. */
    private static void forceDirectory(Path dir) {
        try (FileChannel d = FileChannel.open(dir, StandardOpenOption.READ)) {
            d.force(true);
        } catch (IOException e) {
            // The rename is done and visible; only its durability across a power cut is left to the file system.
        }
    }
}
