package dev.predmon.parse;

import java.io.IOException;
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
import java.util.function.Supplier;

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
 *       program goes on writing to the renamed file until it reopens its log, if it ever does. The follower turns to
 *       the new file only once a file after it holds something and the old one has not grown for
 *       {@value #QUIET_MILLIS} ms: the new file gets a sink of its own, which hears {@code restarted("replaced")}
 *       first, and is read from 0. A file replaced again before that waits its turn, held open too; one that is still
 *       empty when a later one holds something is passed over (rotated twice before the logger reopened).</li>
 *   <li>After the turn the renamed file is still read, with its own partial line and sink, for as long as it grows
 *       ({@link RenamedFiles}): a logger that paused longer than the quiet time goes on there. Each poll reads the
 *       renamed files before the file at the path. One that has not grown for {@link #RELEASE_MILLIS} ms, or is
 *       truncated or deleted, is let go: its unterminated last line is delivered, then {@link LineSink#ended()}.</li>
 *   <li>Deletion: the old handle keeps being drained, since a writer may still hold it, until a new file
 *       appears at the path, or until it has not grown for {@link #RELEASE_MILLIS} ms: then it is closed.</li>
 *   <li>Something at the path that is not a regular file (a FIFO, a directory, a socket) is never opened: opening
 *       a FIFO blocks until a writer comes. It is as if the path were empty, and {@link #obstacle()} says what is
 *       there; a regular file at the path later is read as a replacement.</li>
 *   <li>{@link #release()} closes the file being read to spare a descriptor (and lets renamed files go); the next
 *       {@code poll()} that finds it changed reopens it where reading stopped.</li>
 * </ul>
 * Files are told apart by {@link BasicFileAttributes#fileKey()} (device and inode on Unix), or by creation time
 * where the file system has no keys. Unlike {@code tail -F}, a truncation followed by a rewrite longer than the
 * old read position before the next poll is seen too: the last bytes read are kept and compared with what the
 * file now holds before the read position; if they differ, the file was rewritten and is read from 0. (A
 * rewrite with the very same bytes there cannot be told apart.) Lines are decoded and capped as by {@link LogReader}.
 * Memory is constant: at most one partial line per file read, and one read buffer per thread shared by all
 * followers.
 */
public final class LogFollower implements AutoCloseable {

    /** How long a replaced file must have been quiet before it is finished; {@code tail -F} waits about 5 s. */
    public static final long QUIET_MILLIS = 1000;
    /** How long a file no longer at the path (deleted, renamed away) is held open after it last grew. */
    public static final long RELEASE_MILLIS = 60_000;

    private final Path file;
    /** A sink for each file read: the first one's at construction, each replacement's at its turn. */
    private final Supplier<? extends LineSink> sinks;
    private final int maxLineBytes;
    private final long quietNanos;
    private final long releaseNanos;
    private final LongSupplier clock;

    /** The file being read: null until one was found at the path, and once gone; its channel is null once released. */
    private FileReading reading;
    /** Whether some file was read: the next one is then a replacement. */
    private boolean started;
    /** Whether the file being read was closed by {@link #release()}, and when it had last changed then. */
    private boolean released;
    private FileTime releasedModified;
    /** What is at the path when it is not a regular file ({@code a FIFO}), else null. */
    private String obstacle;
    /** Files found at the path after the one being read, each held open until its turn. */
    private final Replacements waiting = new Replacements();
    /** Files turned away from, read on while they grow. */
    private final RenamedFiles renamed;

    /**
     * @param file the log to follow; it need not exist yet
     * @param sink receives the lines and the restarts of every file read, the renamed files' too
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
        this(file, () -> sink, maxLineBytes, quietNanos, releaseNanos, clock);
        Objects.requireNonNull(sink, "sink");
    }

    /** @param sinks gives the sink of each file read, when the follower takes the file up */
    LogFollower(Path file, Supplier<? extends LineSink> sinks, int maxLineBytes, long quietNanos, long releaseNanos,
                LongSupplier clock) {
        this.file = Objects.requireNonNull(file, "file");
        this.sinks = Objects.requireNonNull(sinks, "sinks");
        this.maxLineBytes = maxLineBytes;
        if (maxLineBytes < 1) {
            throw new IllegalArgumentException("maxLineBytes must be positive, got " + maxLineBytes);
        }
        this.quietNanos = quietNanos;
        this.releaseNanos = releaseNanos;
        this.clock = Objects.requireNonNull(clock, "clock");
        this.renamed = new RenamedFiles(file);
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
     * As {@link #withTimes}, each file read with a sink of its own from {@code sinks}: the lines of a renamed file
     * still written and those of the file at the path, read alternately, then never meet in one sink (a parser).
     */
    public static LogFollower perFile(Path file, Supplier<? extends LineSink> sinks, Duration quiet, Duration release) {
        return new LogFollower(file, sinks, LineSplitter.DEFAULT_MAX_LINE_BYTES, quiet.toNanos(), release.toNanos(),
                System::nanoTime);
    }

    /**
     * Reads whatever is new since the last call, without blocking: the renamed files first, then the file at the path.
     *
     * @return whether anything was consumed (bytes read or a restart signalled)
     * @throws IOException when the file exists but cannot be read
     */
    public boolean poll() throws IOException {
        return poll(true);
    }

    /** As {@link #poll()} without looking at the path (unless a replacement waits): a write was all that changed. */
    public boolean pollWritten() throws IOException {
        return poll(false);
    }

    private boolean poll(boolean look) throws IOException {
        boolean progress = !renamed.isEmpty() && renamed.poll(clock.getAsLong(), releaseNanos);
        if (reading == null || reading.channel == null) {
            return pollClosed() || progress;
        }
        // The open file may have been truncated (and written again) even if it is no longer at the path.
        progress |= reading.readOn(clock.getAsLong());
        if (!look && waiting.isEmpty()) {
            return progress;
        }
        FileAt at = lookForReplacement();
        while (!waiting.isEmpty() && (waiting.full() || (quiet(quietNanos) && waiting.anyHolds()))) {
            finishAndTakeNext(false);
            progress = true;
        }
        if (waiting.isEmpty() && (at == null || !at.identity().equals(reading.identity)) && quiet(releaseNanos)) {
            reading.end(); // gone from the path and quiet for long: its writer is done with it
            reading.close();
            reading = null;
        }
        return progress;
    }

    /** Nothing is open: the path is looked at, and a file there (back) is opened. */
    private boolean pollClosed() throws IOException {
        FileAt at = look();
        if (at == null) {
            return false;
        }
        if (released && reading != null && at.identity().equals(reading.identity)) {
            if (at.size() == reading.position && at.modified().equals(releasedModified)) {
                return false; // unchanged since it was released: no need to open it
            }
            FileChannel opened = at.open();
            if (opened == null) {
                return false;
            }
            reading.channel = opened;
            released = false;
            return poll();
        }
        FileChannel opened = at.open();
        if (opened == null) {
            return false;
        }
        boolean replacement = started;
        if (reading != null) { // the file read before was released: this one replaces it
            reading.end();
        }
        take(opened, at.identity(), replacement);
        return reading.read(clock.getAsLong()) || replacement;
    }

    /**
     * Whether a file found at the path waits for the one being read to be finished: only a later {@link #poll()} can
     * finish it once the quiet time has passed, whether or not anything is written meanwhile.
     */
    public boolean replacing() {
        return !waiting.isEmpty();
    }

    /** Whether a file renamed away from the path is still read: its writer's next write is announced under its name. */
    public boolean readingRenamed() {
        return !renamed.isEmpty();
    }

    /** What is at the path when it is not a regular file ({@code is a FIFO, not a regular file}), if so. */
    public Optional<String> obstacle() {
        return Optional.ofNullable(obstacle).map(k -> "is " + k + ", not a regular file");
    }

    /** How many files this follower holds open now. */
    public int openFiles() {
        return (reading == null || reading.channel == null ? 0 : 1) + waiting.open() + renamed.open();
    }

    /**
     * Closes the file being read to spare a descriptor, unless a replacement waits; a later {@link #poll()} reopens
     * it where reading stopped once it changed. Renamed files still read are read to their end and let go: whatever
     * a writer adds to them, or to a file renamed or deleted meanwhile, is not seen.
     *
     * @return whether a file was closed
     */
    public boolean release() throws IOException {
        if (reading == null || reading.channel == null || !waiting.isEmpty()) {
            return false;
        }
        renamed.letGoAll(clock.getAsLong());
        FileAt at = FileAt.look(file);
        releasedModified = at != null && at.identity().equals(reading.identity) ? at.modified() : null;
        reading.close();
        released = true;
        return true;
    }

    /**
     * Reads to the end of the file and delivers an unterminated last line too (for a single pass over a file
     * that is no longer written), then {@link LineSink#ended()}; a replacement found meanwhile is read to its end
     * after it, and renamed files still read are read to their end and let go first. A later {@link #poll()} goes on
     * from there.
     *
     * @throws NoSuchFileException when the file does not exist and none was ever opened
     * @throws IOException         when the file cannot be read
     */
    public void drainToEnd() throws IOException {
        poll();
        if (reading == null || reading.channel == null) {
            if (obstacle != null) {
                throw new FileSystemException(file.toString(), null, obstacle().orElseThrow());
            }
            throw new NoSuchFileException(file.toString());
        }
        renamed.letGoAll(clock.getAsLong());
        while (!waiting.isEmpty()) {
            finishAndTakeNext(true);
        }
        reading.end();
    }

    @Override
    public void close() throws IOException {
        List<FileChannel> all = new ArrayList<>(renamed.channels());
        all.addAll(waiting.channels());
        if (reading != null && reading.channel != null) {
            all.add(0, reading.channel);
            reading.channel = null;
        }
        waiting.clear();
        FileAt.closeAll(all);
    }

    private boolean quiet(long nanos) {
        return clock.getAsLong() - reading.lastGrowth >= nanos;
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
        if (at == null || at.identity().equals(reading.identity) || waiting.full()
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
     * The file being read is turned away from: it is read on while it grows (or, in a single pass, ended now), and the
     * next file is read from 0 with a sink of its own. A next file that is still empty while one after it holds
     * something is passed over: it was rotated away before its turn.
     */
    private void finishAndTakeNext(boolean draining) throws IOException {
        FileReading done = reading;
        Replacements.Waiting next = waiting.next();
        if (draining) {
            done.end();
            done.close();
        } else {
            renamed.add(done);
        }
        take(next.channel(), next.identity(), true);
        reading.read(clock.getAsLong());
    }

    /** Reads {@code opened} from 0 from now on, with a new sink; a replacement's sink hears so first. */
    private void take(FileChannel opened, Object id, boolean replacement) {
        LineSink sink = sinks.get();
        started = true;
        reading = new FileReading(opened, id, sink, maxLineBytes, clock.getAsLong());
        released = false;
        if (replacement) {
            sink.restarted("replaced");
        }
    }
}
