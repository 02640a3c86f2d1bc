package dev.predmon.monitor;

import dev.predmon.parse.LogFollower;
import dev.predmon.parse.LogFormat;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * Wires a followed log to the predictive monitor: the log's {@link RecordSource} (in the format of the monitor's
 * abstraction: for YARP logs, tail -F and a parser per file, see {@link LogFormat#yarp()}) delivers records to the {@link PredictiveMonitor}, and a rotation restarts it
 * (a new run). The caller owns the loop and its pace ({@link #poll()} never sleeps), so the same wiring serves
 * {@code watch}, the demo and replayed evaluation.
 */
public final class LogWatcher implements AutoCloseable {

    private static final Duration DEFAULT_QUIET = Duration.ofMillis(LogFollower.QUIET_MILLIS);
    static final Duration DEFAULT_RELEASE = Duration.ofMillis(LogFollower.RELEASE_MILLIS);

    private final PredictiveMonitor monitor;
    private final RecordSource source;

    public LogWatcher(Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems) {
        this(formatOf(monitor), log, monitor, problems, record -> { }, record -> { }, DEFAULT_QUIET, DEFAULT_RELEASE);
    }

    /**
     * As above; {@code seen} also gets every record, before the monitor (tests count them across rotations), and a
     * replaced file is finished once it has been {@code quiet} ({@link LogFollower#QUIET_MILLIS} otherwise).
     */
    LogWatcher(Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems, Consumer<LogRecord> seen,
               Duration quiet) {
        this(formatOf(monitor), log, monitor, problems, seen, record -> { }, quiet, DEFAULT_RELEASE);
    }

    /**
     * As the public constructor; {@code taken} also gets every record right after the monitor took it, so that the
     * monitor's run and value already include it (the live view plots each reading of the value in its run).
     */
    public static LogWatcher withRecords(Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems,
                                         Consumer<LogRecord> taken) {
        return new LogWatcher(formatOf(monitor), log, monitor, problems, record -> { }, taken, DEFAULT_QUIET,
                DEFAULT_RELEASE);
    }

    /**
     * As {@link #withRecords}; a file gone from the path is closed once it has not grown for {@code release}; read
     * in {@code format}, or in the abstraction's when null.
     */
    static LogWatcher withRelease(Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems,
                                  Consumer<LogRecord> taken, Duration release, LogFormat format) {
        return new LogWatcher(format == null ? formatOf(monitor) : format, log, monitor, problems, record -> { },
                taken, DEFAULT_QUIET, release);
    }

    /** How the monitor's abstraction reads logs: YARP logs, and ROS 2 recordings when it maps their topics. */
    private static LogFormat formatOf(PredictiveMonitor monitor) {
        return monitor.pipeline().abstraction().format();
    }

    private LogWatcher(LogFormat format, Path log, PredictiveMonitor monitor, Consumer<ParseProblem> problems,
                       Consumer<LogRecord> seen, Consumer<LogRecord> taken, Duration quiet, Duration release) {
        this.monitor = monitor;
        this.source = format.follow(log, new RecordSink() {
            @Override
            public void record(LogRecord record) {
                seen.accept(record);
                monitor.accept(record);
                taken.accept(record);
            }

            @Override
            public void problem(ParseProblem problem) {
                problems.accept(problem);
            }

            @Override
            public void restarted(String reason) {
                monitor.restart(reason);
            }
        }, quiet, release);
    }

    /** Processes whatever was appended since the last call; whether anything was. */
    public boolean poll() throws IOException {
        return source.poll();
    }

    /** As {@link #poll()}, when the only news is a write to the log's file ({@link RecordSource#pollWritten()}). */
    public boolean pollWritten() throws IOException {
        return source.pollWritten();
    }

    /** Reads to the end of the log, completes the trace and stops (for {@code --no-follow} and replay). */
    public void drain() throws IOException {
        source.drain();
        monitor.endOfInput();
    }

    /** Whether a replaced file waits for a later {@link #poll()} to be finished ({@link RecordSource#replacing()}). */
    public boolean replacing() {
        return source.replacing();
    }

    /** Whether a file renamed away at a rotation is still read ({@link RecordSource#readingRenamed()}). */
    public boolean readingRenamed() {
        return source.readingRenamed();
    }

    /** What is at the log's path when it is not a regular file ({@link RecordSource#obstacle()}), if so. */
    public Optional<String> obstacle() {
        return source.obstacle();
    }

    /** What the user should be told of this log once, if anything ({@link RecordSource#takeNotice()}). */
    public Optional<String> takeNotice() {
        return source.takeNotice();
    }

    /** How many files are held open for this log now. */
    public int openFiles() {
        return source.openFiles();
    }

    /** Closes the log's files to spare descriptors ({@link RecordSource#release()}); whether one was closed. */
    public boolean release() throws IOException {
        return source.release();
    }

    /** Lines read since the start or the last rotation (a renamed file's read on since then included). */
    public long lines() {
        return source.lines();
    }

    /** Of those lines, YARP's own before the first record ({@link RecordSource#yarpLines()}). */
    public long yarpLines() {
        return source.yarpLines();
    }

    public PredictiveMonitor monitor() {
        return monitor;
    }

    @Override
    public void close() throws IOException {
        source.close();
    }
}
