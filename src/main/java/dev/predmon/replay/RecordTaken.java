package dev.predmon.replay;

import dev.predmon.parse.LogRecord;
import dev.predmon.property.PropertyView;

/** Told every record of a replayed log right after the monitor took it, with how the checker judged it. */
@FunctionalInterface
public interface RecordTaken {

    /**
     * A record was taken.
     *
     * @param record the record
     * @param run    its run
     * @param judged every property as the monitor's checker judged the record (read-only)
     */
    void taken(LogRecord record, int run, PropertyView judged);
}
