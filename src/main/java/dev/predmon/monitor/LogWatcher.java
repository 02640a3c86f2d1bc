package dev.predmon.monitor;

import dev.predmon.parse.LineSink;
import dev.predmon.parse.LogFollower;
import dev.predmon.parse.LogParser;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * Wires a followed log file to the predictive monitor: {@link LogFollower} (tail -F) feeds lines to a
 * {@link LogParser} per file, whose records go to the {@link PredictiveMonitor}. The caller owns the loop and its
 * pace ({@link #poll()} never sleeps), so the same wiring serves {@code watch}, the demo and replayed evaluation.
 *
 * <p>Rotation: a truncation restarts the file's parser and the monitor at once. A file that replaces another gets a
 * parser of its own, and the monitor starts over (a new run) at the first record read from it, not at the turn:
 * until then, what the old writer adds to the renamed file, which the follower reads on while it grows, continues
 * the run it was in, exactly as if it had been written to one file (a record cut where the writer paused is
 * completed there). Records are taken in the order they are read, each file's in its own order; a poll reads the
 * renamed file before the file at the path. Once the new file has given a record, a record the renamed file still
 * gives goes into the run under way, and the user is told once that two writers are read as one.
 */
public final class LogWatcher implements AutoCloseable {

    private static final Duration DEFAULT_QUIET = Duration.ofMillis(LogFollower.QUIET_MILLIS);
    static final Duration DEFAULT_RELEASE = Duration.ofMillis(LogFollower.RELEASE_MILLIS);

    private final PredictiveMonitor monitor;
    private final Consumer<ParseProblem> problems;
    private final Consumer<LogRecord> seen;
    private final Consumer<LogRecord> taken;
    private final LogFollower follower;
    /** The parser of the file at the path (the file read last taken up). */
    private FileParser current;
    private long lines;
    /** What the user should be told once, or null; whether two writers were told of already. */
    private String notice;
    private boolean toldTwoWriters;

    public LogWatcher(Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems) {
        this(log, monitor, problems, record -> { }, record -> { }, DEFAULT_QUIET, DEFAULT_RELEASE);
    }

    /**
     * As above; {@code seen} also gets every record, before the monitor (tests count them across rotations), and a
     * replaced file is finished once it has been {@code quiet} ({@link LogFollower#QUIET_MILLIS} otherwise).
     */
    LogWatcher(Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems, Consumer<LogRecord> seen,
               Duration quiet) {
        this(log, monitor, problems, seen, record -> { }, quiet, DEFAULT_RELEASE);
    }

    /**
     * As the public constructor; {@code taken} also gets every record right after the monitor took it, so that the
     * monitor's run and battery already include it (the live view plots each battery reading in its run).
     */
    public static LogWatcher withRecords(Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems,
                                         Consumer<LogRecord> taken) {
        return new LogWatcher(log, monitor, problems, record -> { }, taken, DEFAULT_QUIET, DEFAULT_RELEASE);
    }

    /** As {@link #withRecords}; a file gone from the path is closed once it has not grown for {@code release}. */
    static LogWatcher withRelease(Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems,
                                  Consumer<LogRecord> taken, Duration release) {
        return new LogWatcher(log, monitor, problems, record -> { }, taken, DEFAULT_QUIET, release);
    }

    private LogWatcher(Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems, Consumer<LogRecord> seen,
                       Consumer<LogRecord> taken, Duration quiet, Duration release) {
        this.monitor = monitor;
        this.problems = problems;
        this.seen = seen;
        this.taken = taken;
        this.follower = LogFollower.perFile(log, FileParser::new, quiet, release);
    }

    /** The lines of one file the follower reads, parsed on their own, its records given to the monitor. */
    private final class FileParser implements LineSink {

        private final LogParser parser = new LogParser(this::record, problems);
        private final LineSink lines = parser.lineSink();
        /** Whether this file replaced another and has given no record yet: its first one begins a new run. */
        private boolean replacement;
        private boolean gaveRecord;

        FileParser() {
            current = this;
        }

        private void record(LogRecord record) {
            if (replacement) {
                replacement = false;
                monitor.restart("replaced");
            }
            if (this != current && current.gaveRecord && !toldTwoWriters) {
                toldTwoWriters = true;
                notice = "the file renamed away at a rotation is still written after the file now at the path gave "
                        + "records: two writers, whose records are taken in the order they are read, as one run";
            }
            gaveRecord = true;
            seen.accept(record);
            monitor.accept(record);
            taken.accept(record);
        }

        @Override
        public void line(String line) {
            LogWatcher.this.lines++;
            lines.line(line);
        }

        @Override
        public void line(byte[] bytes, int offset, int length) {
            LogWatcher.this.lines++;
            lines.line(bytes, offset, length);
        }

        @Override
        public void overlongLine(long bytes) {
            LogWatcher.this.lines++;
            lines.overlongLine(bytes);
        }

        @Override
        public void lastLine(byte[] bytes, int offset, int length) {
            lines.lastLine(bytes, offset, length);
        }

        @Override
        public void restarted(String reason) {
            LogWatcher.this.lines = 0;
            if (reason.equals("replaced")) {
                replacement = true; // a new parser: nothing of the file before is in it
                return;
            }
            lines.restarted(reason); // reports a record the truncation cut, then starts the parser over
            replacement = false;
            gaveRecord = false;
            monitor.restart(reason);
        }

        @Override
        public void ended() {
            lines.ended(); // a record the file ends in the middle of is reported as cut
        }
    }

    /** Processes whatever was appended since the last call; whether anything was. */
    public boolean poll() throws IOException {
        return follower.poll();
    }

    /** Reads to the end of the file, completes the trace and stops (for {@code --no-follow} and replay). */
    public void drain() throws IOException {
        follower.drainToEnd(); // ends every file's parser
        monitor.endOfInput();
    }

    /** Whether a replaced file waits for a later {@link #poll()} to be finished ({@link LogFollower#replacing()}). */
    public boolean replacing() {
        return follower.replacing();
    }

    /** What is at the log's path when it is not a regular file ({@link LogFollower#obstacle()}), if so. */
    public Optional<String> obstacle() {
        return follower.obstacle();
    }

    /** What the user should be told of this log once since the last call, if anything: two writers read as one. */
    public Optional<String> takeNotice() {
        Optional<String> out = Optional.ofNullable(notice);
        notice = null;
        return out;
    }

    /** Whether a file renamed away at a rotation is still read ({@link LogFollower#readingRenamed()}). */
    public boolean readingRenamed() {
        return follower.readingRenamed();
    }

    /** How many files are held open for this log now. */
    public int openFiles() {
        return follower.openFiles();
    }

    /** Closes the log's file to spare a descriptor ({@link LogFollower#release()}); whether one was closed. */
    public boolean release() throws IOException {
        return follower.release();
    }

    /** Lines read since the start or the last rotation (a renamed file's read on since then included). */
    public long lines() {
        return lines;
    }

    public PredictiveMonitor monitor() {
        return monitor;
    }

    @Override
    public void close() throws IOException {
        follower.close();
    }
}
