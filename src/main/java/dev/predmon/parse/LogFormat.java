package dev.predmon.parse;

import java.nio.file.Path;
import java.time.Duration;

/**
 * An input format: how a log file becomes {@link LogRecord}s. Each way of reading a log is a {@link RecordSource}
 * delivering to a {@link RecordSink}; a second format is a second implementation of this interface.
 */
public interface LogFormat {

    /** YARP monitor logs: console captures, yarplogger's columns and its save files ({@link LogParser}). */
    static LogFormat yarp() {
        return YarpFormat.INSTANCE;
    }

    /**
     * Follows {@code log} as {@code tail -F} does (it need not exist yet), through rotation.
     *
     * @param quiet   how long a replaced file must not have grown before the file after it is read
     * @param release how long a file gone from the path (deleted, renamed away) is held open after it last grew
     */
    RecordSource follow(Path log, RecordSink sink, Duration quiet, Duration release);

    /** As {@link #follow(Path, RecordSink, Duration, Duration)} with the default times (1 s, 60 s). */
    default RecordSource follow(Path log, RecordSink sink) {
        return follow(log, sink, Duration.ofMillis(LogFollower.QUIET_MILLIS),
                Duration.ofMillis(LogFollower.RELEASE_MILLIS));
    }

    /**
     * Reads {@code file}, a log no longer written, once: {@link RecordSource#drain()} reads it whole (as fast as the
     * format allows), and so does the first {@link RecordSource#poll()}.
     */
    RecordSource read(Path file, RecordSink sink);
}
