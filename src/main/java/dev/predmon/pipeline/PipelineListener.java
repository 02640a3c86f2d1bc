package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.compact.IoPair;
import dev.predmon.parse.LogRecord;

/** Receives what the pipeline makes of a log, in order. */
public interface PipelineListener {

    /** Every parsed record, before abstraction (the safety monitor watches these). */
    default void record(LogRecord record) {
    }

    /**
     * A continuous rule's reply with its raw value, by the rule's input ({@link Abstraction#continuousReading}),
     * after {@link #record} of the same record.
     */
    default void reading(String input, double value) {
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
