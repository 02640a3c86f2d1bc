package dev.predmon.pipeline;

import dev.predmon.compact.IoPair;
import dev.predmon.parse.LogRecord;

/** Receives what the pipeline makes of a log, in order. */
public interface PipelineListener {

    /** Every parsed record, before abstraction (the safety monitor watches these). */
    default void record(LogRecord record) {
    }

    /** A compacted query/reply pair; {@code trigger} is the record whose arrival completed it. */
    void pair(IoPair pair, LogRecord trigger);
}
