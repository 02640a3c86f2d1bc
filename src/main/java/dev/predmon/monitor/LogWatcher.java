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
 * Wires a followed log file to the predictive monitor: {@link LogFollower} (tail -F) feeds lines to the
 * {@link LogParser}, whose records go to the {@link PredictiveMonitor}; rotation restarts both. The caller owns
 * the loop and its pace ({@link #poll()} never sleeps), so the same wiring serves {@code watch}, the demo and
 * replayed evaluation.
 */
public final class LogWatcher implements AutoCloseable {

    private static final Duration DEFAULT_QUIET = Duration.ofMillis(LogFollower.QUIET_MILLIS);
    static final Duration DEFAULT_RELEASE = Duration.ofMillis(LogFollower.RELEASE_MILLIS);

    private final PredictiveMonitor monitor;
    private final LogParser parser;
    private final LogFollower follower;
    private long lines;

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
        this.parser = new LogParser(record -> {
            seen.accept(record);
            monitor.accept(record);
            taken.accept(record);
        }, problems);
        LineSink lines = parser.lineSink();
        this.follower = LogFollower.withTimes(log, new LineSink() {
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
                lines.restarted(reason); // reports a record the rotation cut, then starts the parser over
                monitor.restart(reason);
            }
        }, quiet, release);
    }

    /** Processes whatever was appended since the last call; whether anything was. */
    public boolean poll() throws IOException {
        return follower.poll();
    }

    /** Reads to the end of the file, completes the trace and stops (for {@code --no-follow} and replay). */
    public void drain() throws IOException {
        follower.drainToEnd();
        parser.endOfInput();
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

    /** What the user should be told of this log once, if anything ({@link LogFollower#takeNotice()}). */
    public Optional<String> takeNotice() {
        return follower.takeNotice();
    }

    /** How many files are held open for this log now. */
    public int openFiles() {
        return follower.openFiles();
    }

    /** Closes the log's file to spare a descriptor ({@link LogFollower#release()}); whether one was closed. */
    public boolean release() throws IOException {
        return follower.release();
    }

    /** Lines read since the start or the last rotation. */
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
