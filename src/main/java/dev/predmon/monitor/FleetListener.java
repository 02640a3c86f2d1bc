package dev.predmon.monitor;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;

import java.io.IOException;
import java.nio.file.Path;

/** What a fleet reports, always from the thread that polls it. */
public interface FleetListener {

    /** A log is watched from now on (it may not exist yet). */
    default void added(WatchedLog log) {
    }

    /**
     * {@code log} was deleted long ago ({@link DeletedLogs}): the fleet no longer watches it, and forgets its monitor;
     * its runs' verdicts are what they were. A file at its path later is a new log.
     */
    default void forgotten(WatchedLog log) {
    }

    /** An event of {@code log}'s monitor, in its log order. */
    void event(WatchedLog log, MonitorEvent event);

    /** A record of {@code log}, just after its monitor took it (see {@link LogWatcher#withRecords}). */
    default void record(WatchedLog log, LogRecord record) {
    }

    /** Something in {@code log} the parser could not take as a record. */
    default void problem(WatchedLog log, ParseProblem problem) {
    }

    /** A poll found {@code log} grown (or truncated or replaced). */
    default void grew(WatchedLog log) {
    }

    /** While following, twice a second, whether or not any log changed. */
    default void pulse() {
    }

    /** Looking for new logs under a directory or glob failed; the fleet goes on and looks again later. */
    default void rescanFailed(IOException e) {
    }

    /**
     * The operating system's file-change notification is unavailable for the logs in {@code dir}, or for every
     * log when {@code dir} is null, because of {@code why} (a few words): they are polled every {@code pauseNanos}
     * instead. Told once per directory while following, never with forced polling (it was asked for).
     */
    default void unnotified(Path dir, String why, long pauseNanos) {
    }

    /**
     * Following has begun, and every log watched from the start has been read as far as it went then: what it
     * held is history, and every event from now on is news (a warning to send to the robot).
     */
    default void caughtUp() {
    }

    /**
     * The listener's own periodic work while following (a heartbeat line), on the following thread: called as
     * following begins and then each time the pause it returned has passed.
     *
     * @return the pause until the next call, in nanoseconds; {@link Long#MAX_VALUE} for none
     */
    default long beat() {
        return Long.MAX_VALUE;
    }

    /**
     * One line the user should read while following, naming the log it is about: something at its path that is
     * not a file (a FIFO, a directory), a read that failed, the fleet closing idle logs for want of descriptors.
     * Each is told once, until it changes; the fleet goes on watching every log.
     */
    default void notice(String line) {
    }
}
