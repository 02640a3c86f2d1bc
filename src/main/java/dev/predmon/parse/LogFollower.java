package dev.predmon.parse;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Objects;

/**
 * Follows a log file as {@code tail -F} does, for the live monitor: each {@link #poll()} delivers the complete
 * lines appended since the previous one. It never sleeps; the caller owns the waiting loop.
 *
 * <ul>
 *   <li>A file that does not exist yet is waited for: {@code poll()} returns {@code false} until it appears.</li>
 *   <li>Growth: complete lines are delivered; an unterminated last line is held until its newline arrives,
 *       since a writer may cut lines (and records) anywhere.</li>
 *   <li>Truncation (size below the read position, as copytruncate rotation does): the held partial line is
 *       delivered, then {@link LineSink#restarted restarted("truncated")}, then the file is read from offset 0.</li>
 *   <li>Replacement (the path names another file: rename rotation, delete and recreate): the old open file is
 *       drained to its end (its unterminated last line included), then {@code restarted("replaced")}, then the
 *       new file is read from 0.</li>
 *   <li>Deletion: the old handle keeps being drained, since a writer may still hold it, until a new file
 *       appears at the path.</li>
 * </ul>
 * Files are told apart by {@link BasicFileAttributes#fileKey()} (device and inode on Unix), or by creation time
 * where the file system has no keys. Unlike {@code tail -F}, a truncation followed by a rewrite longer than the
 * old read position before the next poll is seen too: the last bytes read are kept and compared with what the
 * file now holds before the read position; if they differ, the file was rewritten and is read from 0. (A
 * rewrite with the very same bytes there cannot be told apart.) Lines are decoded and capped as by {@link LogReader}.
 * Memory is constant: one read buffer and at most one partial line.
 */
public final class LogFollower implements AutoCloseable {

    private static final int BUFFER_BYTES = 64 * 1024;
    /** How many of the last bytes read are kept to notice a rewrite: enough for a time stamp and more. */
    private static final int TAIL_BYTES = 64;

    private final Path file;
    private final LineSink sink;
    private final LineSplitter splitter;
    private final ByteBuffer buffer = ByteBuffer.allocate(BUFFER_BYTES);
    /** The bytes just before {@link #position}, as read: {@code tail[0, tailLength)}. */
    private final byte[] tail = new byte[TAIL_BYTES];
    private int tailLength;
    private final ByteBuffer check = ByteBuffer.allocate(TAIL_BYTES);

    private FileChannel channel;
    private Object identity;
    private long position;
    /** Whether a file was ever opened, so that the next one is a replacement. */
    private boolean openedBefore;

    /**
     * @param file the log to follow; it need not exist yet
     * @param sink receives the lines and the restarts
     */
    public LogFollower(Path file, LineSink sink) {
        this(file, sink, LineSplitter.DEFAULT_MAX_LINE_BYTES);
    }

    LogFollower(Path file, LineSink sink, int maxLineBytes) {
        this.file = Objects.requireNonNull(file, "file");
        this.sink = Objects.requireNonNull(sink, "sink");
        this.splitter = new LineSplitter(maxLineBytes, sink);
    }

    /**
     * Reads whatever is new since the last call, without blocking.
     *
     * @return whether anything was consumed (bytes read or a restart signalled)
     * @throws IOException when the file exists but cannot be read
     */
    public boolean poll() throws IOException {
        if (channel == null) {
            return open() | readAvailable();
        }
        Object current = identityOf(file);
        // The open file may have been truncated (and written again) even if it is no longer at the path.
        boolean truncated = channel.size() < position || rewritten();
        if (truncated) {
            splitter.finish();
            sink.restarted("truncated");
            position = 0;
            tailLength = 0;
        }
        if (current != null && current.equals(identity)) {
            return readAvailable() | truncated;
        }
        boolean progress = readAvailable() | truncated;
        if (current == null) {
            return progress;
        }
        splitter.finish();
        closeChannel();
        return open() | readAvailable() | progress;
    }

    /**
     * Reads to the end of the file and delivers an unterminated last line too (for a single pass over a file
     * that is no longer written). A later {@link #poll()} goes on from there.
     *
     * @throws NoSuchFileException when the file does not exist and none was ever opened
     * @throws IOException         when the file cannot be read
     */
    public void drainToEnd() throws IOException {
        poll();
        if (channel == null && !openedBefore) {
            throw new NoSuchFileException(file.toString());
        }
        splitter.finish();
    }

    @Override
    public void close() throws IOException {
        closeChannel();
    }

    /** Opens the file at the path if there is one; returns whether it did. */
    private boolean open() throws IOException {
        Object before = identityOf(file);
        if (before == null) {
            return false;
        }
        FileChannel opened;
        try {
            opened = FileChannel.open(file, StandardOpenOption.READ);
        } catch (NoSuchFileException gone) {
            // Deleted between the look and the open: the same as not there yet, try again at the next poll.
            return false;
        }
        if (!before.equals(identityOf(file))) {
            // Replaced between the look and the open: we may hold the wrong file, look again next time.
            opened.close();
            return false;
        }
        if (openedBefore) {
            sink.restarted("replaced");
        }
        channel = opened;
        identity = before;
        position = 0;
        tailLength = 0;
        openedBefore = true;
        return true;
    }

    private boolean readAvailable() throws IOException {
        if (channel == null) {
            return false;
        }
        boolean progress = false;
        while (true) {
            buffer.clear();
            int n = channel.read(buffer, position);
            if (n <= 0) {
                return progress;
            }
            position += n;
            progress = true;
            remember(buffer.array(), n);
            splitter.feed(buffer.array(), 0, n);
        }
    }

    /** Keeps the last {@value #TAIL_BYTES} bytes read, the {@code n} bytes of {@code bytes} being the newest. */
    private void remember(byte[] bytes, int n) {
        if (n >= TAIL_BYTES) {
            System.arraycopy(bytes, n - TAIL_BYTES, tail, 0, TAIL_BYTES);
            tailLength = TAIL_BYTES;
            return;
        }
        int keep = Math.min(tailLength, TAIL_BYTES - n);
        System.arraycopy(tail, tailLength - keep, tail, 0, keep);
        System.arraycopy(bytes, 0, tail, keep, n);
        tailLength = keep + n;
    }

    /**
     * Whether the bytes before the read position are no longer those read there: the file was truncated and
     * written again past the old position between two polls (copytruncate rotation while the logger writes).
     */
    private boolean rewritten() throws IOException {
        if (tailLength == 0) {
            return false;
        }
        check.clear().limit(tailLength);
        long at = position - tailLength;
        while (check.hasRemaining()) {
            int n = channel.read(check, at + check.position());
            if (n <= 0) {
                return true; // shorter than it was: truncated
            }
        }
        return !java.util.Arrays.equals(check.array(), 0, tailLength, tail, 0, tailLength);
    }

    private void closeChannel() throws IOException {
        if (channel != null) {
            FileChannel closing = channel;
            channel = null;
            identity = null;
            closing.close();
        }
    }

    /** The identity of the file at {@code path}, or {@code null} if there is none. */
    private static Object identityOf(Path path) throws IOException {
        BasicFileAttributes attributes;
        try {
            attributes = Files.readAttributes(path, BasicFileAttributes.class);
        } catch (NoSuchFileException absent) {
            return null;
        }
        Object key = attributes.fileKey();
        return key != null ? key : attributes.creationTime();
    }
}
