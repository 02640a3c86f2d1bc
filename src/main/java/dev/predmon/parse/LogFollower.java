package dev.predmon.parse;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;

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
 *   <li>Replacement (the path names another file: rename rotation, delete and recreate): the new file is opened at
 *       once, so that nothing written to it is lost, but the old file is read on as long as its writer may still
 *       write to it. logrotate's default ({@code create}) renames the log and creates an empty one, and the
 *       program goes on writing to the renamed file until it reopens its log, if it ever does. The old file is
 *       therefore finished (its unterminated last line included) only once the new file holds something and the
 *       old one has not grown for {@value #QUIET_MILLIS} ms; then {@code restarted("replaced")}, then the new
 *       file is read from 0. A file replaced again before that waits its turn, held open too.</li>
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

    /** How long a replaced file must have been quiet before it is finished; {@code tail -F} waits about 5 s. */
    public static final long QUIET_MILLIS = 1000;
    private static final int BUFFER_BYTES = 64 * 1024;
    /** How many of the last bytes read are kept to notice a rewrite: enough for a time stamp and more. */
    private static final int TAIL_BYTES = 64;
    /** Replacements held open at most while the file read is still written: beyond, the oldest is finished at once. */
    private static final int MAX_WAITING = 8;

    private final Path file;
    private final LineSink sink;
    private final LineSplitter splitter;
    private final long quietNanos;
    private final LongSupplier clock;
    private final ByteBuffer buffer = ByteBuffer.allocate(BUFFER_BYTES);
    /** The bytes just before {@link #position}, as read: {@code tail[0, tailLength)}. */
    private final byte[] tail = new byte[TAIL_BYTES];
    private int tailLength;
    private final ByteBuffer check = ByteBuffer.allocate(TAIL_BYTES);

    /** The file being read; {@code null} until one was found at the path. */
    private FileChannel channel;
    private Object identity;
    private long position;
    /** {@link #clock} when the file being read last grew (or was opened). */
    private long lastGrowth;
    /** Files found at the path after the one being read, oldest first, each held open until its turn. */
    private final ArrayDeque<Waiting> waiting = new ArrayDeque<>();

    /** A replacement held open until the file before it is finished. */
    private record Waiting(FileChannel channel, Object identity) {
    }

    /**
     * @param file the log to follow; it need not exist yet
     * @param sink receives the lines and the restarts
     */
    public LogFollower(Path file, LineSink sink) {
        this(file, sink, LineSplitter.DEFAULT_MAX_LINE_BYTES);
    }

    LogFollower(Path file, LineSink sink, int maxLineBytes) {
        this(file, sink, maxLineBytes, TimeUnit.MILLISECONDS.toNanos(QUIET_MILLIS), System::nanoTime);
    }

    /**
     * @param quietNanos how long a replaced file must not have grown before it is finished (0: at once)
     * @param clock      the time in nanoseconds, as {@link System#nanoTime()}
     */
    LogFollower(Path file, LineSink sink, int maxLineBytes, long quietNanos, LongSupplier clock) {
        this.file = Objects.requireNonNull(file, "file");
        this.sink = Objects.requireNonNull(sink, "sink");
        this.splitter = new LineSplitter(maxLineBytes, sink);
        this.quietNanos = quietNanos;
        this.clock = Objects.requireNonNull(clock, "clock");
    }

    /** A follower that finishes a replaced file once it has been quiet for {@code quiet} ({@code watch}'s is 1 s). */
    public static LogFollower withQuiet(Path file, LineSink sink, Duration quiet) {
        return new LogFollower(file, sink, LineSplitter.DEFAULT_MAX_LINE_BYTES, quiet.toNanos(), System::nanoTime);
    }

    /**
     * Reads whatever is new since the last call, without blocking.
     *
     * @return whether anything was consumed (bytes read or a restart signalled)
     * @throws IOException when the file exists but cannot be read
     */
    public boolean poll() throws IOException {
        if (channel == null) {
            Object found = identityOf(file);
            FileChannel opened = found == null ? null : openAt(found);
            if (opened == null) {
                return false;
            }
            take(opened, found);
            return readAvailable();
        }
        // The open file may have been truncated (and written again) even if it is no longer at the path.
        boolean progress = false;
        if (channel.size() < position || rewritten()) {
            splitter.finish();
            sink.restarted("truncated");
            position = 0;
            tailLength = 0;
            progress = true;
        }
        progress |= readAvailable();
        lookForReplacement();
        while (!waiting.isEmpty() && (waiting.size() >= MAX_WAITING
                || (clock.getAsLong() - lastGrowth >= quietNanos && waiting.peek().channel().size() > 0))) {
            finishAndTakeNext();
            readAvailable();
            progress = true;
        }
        return progress;
    }

    /**
     * Whether a file found at the path waits for the one being read to be finished: only a later {@link #poll()} can
     * finish it once the quiet time has passed, whether or not anything is written meanwhile.
     */
    public boolean replacing() {
        return !waiting.isEmpty();
    }

    /**
     * Reads to the end of the file and delivers an unterminated last line too (for a single pass over a file
     * that is no longer written); a replacement found meanwhile is read to its end after it. A later
     * {@link #poll()} goes on from there.
     *
     * @throws NoSuchFileException when the file does not exist and none was ever opened
     * @throws IOException         when the file cannot be read
     */
    public void drainToEnd() throws IOException {
        poll();
        if (channel == null) {
            throw new NoSuchFileException(file.toString());
        }
        while (!waiting.isEmpty()) {
            finishAndTakeNext();
            readAvailable();
        }
        splitter.finish();
    }

    @Override
    public void close() throws IOException {
        IOException first = null;
        for (FileChannel c : openChannels()) {
            try {
                c.close();
            } catch (IOException e) {
                if (first == null) {
                    first = e;
                } else {
                    first.addSuppressed(e);
                }
            }
        }
        channel = null;
        waiting.clear();
        if (first != null) {
            throw first;
        }
    }

    private List<FileChannel> openChannels() {
        List<FileChannel> all = new ArrayList<>();
        if (channel != null) {
            all.add(channel);
        }
        waiting.forEach(w -> all.add(w.channel()));
        return all;
    }

    /** Opens a file found at the path that is neither the one read nor one waiting, and queues it. */
    private void lookForReplacement() throws IOException {
        Object found = identityOf(file);
        if (found == null || found.equals(identity) || waiting.size() >= MAX_WAITING
                || waiting.stream().anyMatch(w -> w.identity().equals(found))) {
            return; // deleted (the old handle is drained on), unchanged, or known
        }
        FileChannel opened = openAt(found);
        if (opened != null) {
            waiting.add(new Waiting(opened, found));
        }
    }

    /** The file being read is done: its last line goes out, then the restart, then the next file from 0. */
    private void finishAndTakeNext() throws IOException {
        splitter.finish();
        FileChannel done = channel;
        Waiting next = waiting.poll();
        take(next.channel(), next.identity());
        done.close();
        sink.restarted("replaced");
    }

    private void take(FileChannel opened, Object id) {
        channel = opened;
        identity = id;
        position = 0;
        tailLength = 0;
        lastGrowth = clock.getAsLong();
    }

    /** Opens the file at the path, which had identity {@code before}; null if it went or changed meanwhile. */
    private FileChannel openAt(Object before) throws IOException {
        FileChannel opened;
        try {
            opened = FileChannel.open(file, StandardOpenOption.READ);
        } catch (NoSuchFileException gone) {
            // Deleted between the look and the open: the same as not there yet, try again at the next poll.
            return null;
        }
        if (!before.equals(identityOf(file))) {
            // Replaced between the look and the open: we may hold the wrong file, look again next time.
            opened.close();
            return null;
        }
        return opened;
    }

    private boolean readAvailable() throws IOException {
        boolean progress = false;
        while (true) {
            buffer.clear();
            int n = channel.read(buffer, position);
            if (n <= 0) {
                if (progress) {
                    lastGrowth = clock.getAsLong();
                }
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
        return !Arrays.equals(check.array(), 0, tailLength, tail, 0, tailLength);
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
