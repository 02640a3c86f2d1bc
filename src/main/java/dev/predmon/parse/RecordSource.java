package dev.predmon.parse;

import java.io.IOException;
import java.util.Optional;

/**
 * A log's records, as one input format reads them ({@link LogFormat}), delivered to the {@link RecordSink} the source
 * was opened with: polled while the log is followed, or drained to its end. The layers above (the monitor, the
 * learner's traces, reports) know records only through this, so that another format needs no change there.
 *
 * <p>The methods with defaults describe a followed file (rotation, descriptors); a source without files keeps them.
 */
public interface RecordSource extends AutoCloseable {

    /**
     * Reads whatever is new since the last call, without blocking.
     *
     * @return whether anything was consumed (bytes read or a restart signalled)
     * @throws IOException when the log exists but cannot be read
     */
    boolean poll() throws IOException;

    /**
     * As {@link #poll()}, when the only news is that the log's file was written (no file created, renamed or deleted
     * at its path): the path need not be looked at again, so a source may skip that look. A truncation is still seen.
     */
    default boolean pollWritten() throws IOException {
        return poll();
    }

    /**
     * Reads to the end of the log and completes it: a record left in progress is reported as cut. For a single pass
     * over a log no longer written ({@code --no-follow}, learning, reports).
     *
     * @throws java.nio.file.NoSuchFileException when the log does not exist
     * @throws IOException                       when it cannot be read
     */
    void drain() throws IOException;

    /** Lines read since the start or the last rotation. */
    long lines();

    /**
     * Of those lines, how many before the first record were YARP's own ({@code Port /monitor active at ...}): a
     * monitor started before the robot prints them and nothing else until the robot's first message.
     */
    default long yarpLines() {
        return 0;
    }

    /** Whether a file found at the log's path waits for the one being read to be finished by a later poll. */
    default boolean replacing() {
        return false;
    }

    /** Whether a file renamed away at a rotation is still read: its writer's writes are not announced at the path. */
    default boolean readingRenamed() {
        return false;
    }

    /** What is at the log's path when it is not a regular file ({@code is a FIFO, not a regular file}), if so. */
    default Optional<String> obstacle() {
        return Optional.empty();
    }

    /** What the user should be told of this log once since the last call, if anything. */
    default Optional<String> takeNotice() {
        return Optional.empty();
    }

    /** How many files the source holds open now. */
    default int openFiles() {
        return 0;
    }

    /**
     * Closes the files held to spare descriptors; a later {@link #poll()} reopens what changed.
     *
     * @return whether a file was closed
     */
    default boolean release() throws IOException {
        return false;
    }

    @Override
    void close() throws IOException;
}
