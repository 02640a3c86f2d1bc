package dev.predmon.parse;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
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
 *       therefore finished (its unterminated last line included) only once a file after it holds something and
 *       the old one has not grown for {@value #QUIET_MILLIS} ms; then {@code restarted("replaced")}, then the new
 *       file is read from 0. A file replaced again before that waits its turn, held open too; one that is still
 *       empty when a later one holds something is passed over (rotated twice before the logger reopened).</li>
 *   <li>Deletion: the old handle keeps being drained, since a writer may still hold it, until a new file
 *       appears at the path, or until it has not grown for {@link #RELEASE_MILLIS} ms: then it is closed.</li>
 *   <li>Something at the path that is not a regular file (a FIFO, a directory, a socket) is never opened: opening
 *       a FIFO blocks until a writer comes. It is as if the path were empty, and {@link #obstacle()} says what is
 *       there; a regular file at the path later is read as a replacement.</li>
 *   <li>{@link #release()} closes the file being read to spare a descriptor; the next {@code poll()} that finds it
 *       changed reopens it where reading stopped.</li>
 * </ul>
 * Files are told apart by {@link BasicFileAttributes#fileKey()} (device and inode on Unix), or by creation time
 * where the file system has no keys. Unlike {@code tail -F}, a truncation followed by a rewrite longer than the
 * old read position before the next poll is seen too: the last bytes read are kept and compared with what the
 * file now holds before the read position; if they differ, the file was rewritten and is read from 0. (A
 * rewrite with the very same bytes there cannot be told apart.) Lines are decoded and capped as by {@link LogReader}.
 * Memory is constant: at most one partial line, and one read buffer per thread shared by all followers.
 */
public final class LogFollower implements AutoCloseable {

    /** How long a replaced file must have been quiet before it is finished; {@code tail -F} waits about 5 s. */
    public static final long QUIET_MILLIS = 1000;
    /** How long a file no longer at the path (deleted, renamed away) is held open after it last grew. */
    public static final long RELEASE_MILLIS = 60_000;
    private static final int BUFFER_BYTES = 64 * 1024;
    /** One read buffer per thread: a fleet of thousands of logs polled by one thread holds one. */
    private static final ThreadLocal<byte[]> BUFFER = ThreadLocal.withInitial(() -> new byte[BUFFER_BYTES]);

    private final Path file;
    private final LineSink sink;
    private final LineSplitter splitter;
    private final long quietNanos;
    private final long releaseNanos;
    private final LongSupplier clock;
    /** The last bytes read, to notice a rewrite. */
    private final ReadTail tail = new ReadTail();

    /** The file being read; {@code null} until one was found at the path, once released, or once gone. */
    private FileChannel channel;
    /** The identity of the file being read (kept while it is released); null before the first and once gone. */
    private Object identity;
    private long position;
    /** {@link #clock} when the file being read last grew (or was opened). */
    private long lastGrowth;
    /** Whether some file was read: the next one is then a replacement. */
    private boolean started;
    /** Whether the file being read was closed by {@link #release()}, and when it had last changed then. */
    private boolean released;
    private FileTime releasedModified;
    /** What is at the path when it is not a regular file ({@code a FIFO}), else null. */
    private String obstacle;
    /** What the user should be told once, or null. */
    private String notice;
    /** Files found at the path after the one being read, each held open until its turn. */
    private final Replacements waiting = new Replacements();

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
        this(file, sink, maxLineBytes, quietNanos, TimeUnit.MILLISECONDS.toNanos(RELEASE_MILLIS), clock);
    }

    /** @param releaseNanos how long a file gone from the path is held open after it last grew */
    LogFollower(Path file, LineSink sink, int maxLineBytes, long quietNanos, long releaseNanos, LongSupplier clock) {
        this.file = Objects.requireNonNull(file, "file");
        this.sink = Objects.requireNonNull(sink, "sink");
        this.splitter = new LineSplitter(maxLineBytes, sink);
        this.quietNanos = quietNanos;
        this.releaseNanos = releaseNanos;
        this.clock = Objects.requireNonNull(clock, "clock");
    }

    /** A follower that finishes a replaced file once it has been quiet for {@code quiet} ({@code watch}'s is 1 s). */
    public static LogFollower withQuiet(Path file, LineSink sink, Duration quiet) {
        return withTimes(file, sink, quiet, Duration.ofMillis(RELEASE_MILLIS));
    }

    /** As {@link #withQuiet}; a file gone from the path is closed once it has not grown for {@code release}. */
    public static LogFollower withTimes(Path file, LineSink sink, Duration quiet, Duration release) {
        return new LogFollower(file, sink, LineSplitter.DEFAULT_MAX_LINE_BYTES, quiet.toNanos(), release.toNanos(),
                System::nanoTime);
    }

    /**
     * Reads whatever is new since the last call, without blocking.
     *
     * @return whether anything was consumed (bytes read or a restart signalled)
     * @throws IOException when the file exists but cannot be read
     */
    public boolean poll() throws IOException {
        if (channel == null) {
            return pollClosed();
        }
        // The open file may have been truncated (and written again) even if it is no longer at the path.
        boolean progress = false;
        if (channel.size() < position || tail.rewritten(channel, position)) {
            splitter.finish();
            sink.restarted("truncated");
            position = 0;
            tail.clear();
            progress = true;
        }
        progress |= readAvailable();
        FileAt at = lookForReplacement();
        while (!waiting.isEmpty() && (waiting.full() || (quiet(quietNanos) && waiting.anyHolds()))) {
            finishAndTakeNext();
            readAvailable();
            progress = true;
        }
        long lost = waiting.retiredGrowth(clock.getAsLong(), releaseNanos);
        if (lost > 0) {
            notice = "the file renamed away at the last rotation grew by " + lost + " bytes after the file now at "
                    + "the path was taken up: a writer went on in it, and what it wrote there is not read";
        }
        if (waiting.isEmpty() && (at == null || !at.identity().equals(identity)) && quiet(releaseNanos)) {
            splitter.finish(); // gone from the path and quiet for long: its writer is done with it
            channel.close();
            channel = null;
            identity = null;
        }
        return progress;
    }

    /** Nothing is open: the path is looked at, and a file there (back) is opened. */
    private boolean pollClosed() throws IOException {
        FileAt at = look();
        if (at == null) {
            return false;
        }
        if (released && at.identity().equals(identity)) {
            if (at.size() == position && at.modified().equals(releasedModified)) {
                return false; // unchanged since it was released: no need to open it
            }
            FileChannel opened = at.open();
            if (opened == null) {
                return false;
            }
            channel = opened;
            released = false;
            return poll();
        }
        FileChannel opened = at.open();
        if (opened == null) {
            return false;
        }
        if (started) { // the file read before was released or is gone: this one replaces it
            splitter.finish();
            take(opened, at.identity());
            sink.restarted("replaced");
            readAvailable();
            return true;
        }
        started = true;
        take(opened, at.identity());
        return readAvailable();
    }

    /**
     * Whether a file found at the path waits for the one being read to be finished: only a later {@link #poll()} can
     * finish it once the quiet time has passed, whether or not anything is written meanwhile.
     */
    public boolean replacing() {
        return !waiting.isEmpty();
    }

    /** What is at the path when it is not a regular file ({@code is a FIFO, not a regular file}), if so. */
    public Optional<String> obstacle() {
        return Optional.ofNullable(obstacle).map(k -> "is " + k + ", not a regular file");
    }

    /** What the user should be told of this log once since the last call, if anything: writes that are not read. */
    public Optional<String> takeNotice() {
        Optional<String> out = Optional.ofNullable(notice);
        notice = null;
        return out;
    }

    /** How many files this follower holds open now. */
    public int openFiles() {
        return (channel == null ? 0 : 1) + waiting.open();
    }

    /**
     * Closes the file being read to spare a descriptor, unless a replacement waits; a later {@link #poll()} reopens
     * it where reading stopped once it changed. Whatever a writer adds to a file renamed or deleted meanwhile is not
     * seen.
     *
     * @return whether a file was closed
     */
    public boolean release() throws IOException {
        if (channel == null || !waiting.isEmpty()) {
            return false;
        }
        waiting.closeRetired();
        FileAt at = FileAt.look(file);
        releasedModified = at != null && at.identity().equals(identity) ? at.modified() : null;
        channel.close();
        channel = null;
        released = true;
        return true;
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
            if (obstacle != null) {
                throw new FileSystemException(file.toString(), null, obstacle().orElseThrow());
            }
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
        List<FileChannel> all = new ArrayList<>(waiting.channels());
        if (channel != null) {
            all.add(0, channel);
        }
        channel = null;
        waiting.clear();
        FileAt.closeAll(all);
    }

    private boolean quiet(long nanos) {
        return clock.getAsLong() - lastGrowth >= nanos;
    }

    /** The file at the path, noting what is there when it is not a regular file. */
    private FileAt look() throws IOException {
        FileAt at = FileAt.look(file);
        obstacle = at == null || at.regular() ? null : at.kind();
        return at;
    }

    /** Opens a regular file found at the path that is neither the one read nor one waiting, and queues it. */
    private FileAt lookForReplacement() throws IOException {
        FileAt at = look();
        if (at == null || at.identity().equals(identity) || waiting.full()
                || waiting.holds(at.identity())) {
            return at; // deleted (the old handle is drained on), unchanged, or known
        }
        FileChannel opened = at.open();
        if (opened != null) {
            waiting.add(opened, at.identity());
        }
        return at;
    }

    /**
     * The file being read is done: its last line goes out, then the restart, then the next file from 0. A next file
     * that is still empty while one after it holds something is passed over: it was rotated away before its turn.
     */
    private void finishAndTakeNext() throws IOException {
        splitter.finish();
        FileChannel done = channel;
        Replacements.Waiting next = waiting.next();
        take(next.channel(), next.identity());
        waiting.retire(done, clock.getAsLong());
        sink.restarted("replaced");
    }

    private void take(FileChannel opened, Object id) {
        channel = opened;
        identity = id;
        position = 0;
        tail.clear();
        released = false;
        lastGrowth = clock.getAsLong();
    }

    private boolean readAvailable() throws IOException {
        byte[] bytes = BUFFER.get();
        ByteBuffer buffer = ByteBuffer.wrap(bytes);
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
            tail.remember(bytes, n);
            splitter.feed(bytes, 0, n);
        }
    }
}
