package dev.predmon.pipeline;

import dev.predmon.abstraction.Classification;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.compact.IoPair;
import dev.predmon.parse.LogRecord;

/** Receives what the pipeline makes of a log, in order. */
public interface PipelineListener {

    /** Every parsed record, before abstraction (the safety monitor watches these). */
    default void record(LogRecord record) {
    }

    /**
     * The first interface message of its kind that no abstraction rule maps (since the start or the last reset):
     * reported, never silently dropped.
     */
    default void unmapped(UnmappedMessage message, LogRecord record) {
    }

    /**
     * {@code record} is a message of the robot's own interface that the abstraction cannot name (a place no training
     * run went to, a reply no rule takes: {@link UnmappedMessages#novelty}), each one, after {@link #unmapped}: the
     * trace misses a step there.
     */
    default void gap(LogRecord record) {
    }

    /**
     * {@code record}, after {@link #record}, was mapped by the abstraction to {@code c}'s symbol (before
     * hysteresis): a listener that needs more of it (the noise readings) reads it from here instead of
     * classifying the record again.
     */
    default void mapped(LogRecord record, Classification.Mapped c) {
    }

    /** A compacted query/reply pair; {@code trigger} is the record whose arrival completed it. */
    void pair(IoPair pair, LogRecord trigger);

    /**
     * {@code first} begins run number {@code run} (1, 2, ...) of a log that holds several; the previous run's last
     * pairs were delivered before. Run 0 begins with the log and is not announced.
     */
    default void runStarted(int run, LogRecord first) {
    }
}
