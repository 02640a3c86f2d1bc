package dev.predmon.monitor;

import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.pipeline.TracePipeline;
import dev.predmon.pipeline.UnmappedCounts;

import java.util.Map;

/**
 * What a log's pipeline counted before its restarts. The pipeline counts from 0 again after a truncation or
 * replacement, as it reads a new file; what {@code watch} reports at its end counts everything since it started.
 */
final class LogTotals {

    private long records;
    private long interfaceRecords;
    /** Bounded as each pipeline's are: a log rotated daily for months adds no kinds beyond the bound. */
    private final UnmappedCounts unmapped = new UnmappedCounts();

    /** Adds what {@code pipeline} counted, just before it is reset. */
    void add(TracePipeline pipeline) {
        records += pipeline.records();
        interfaceRecords += pipeline.interfaceRecords();
        unmapped.addAll(pipeline.unmapped());
    }

    long records(TracePipeline now) {
        return records + now.records();
    }

    long interfaceRecords(TracePipeline now) {
        return interfaceRecords + now.interfaceRecords();
    }

    Map<UnmappedMessage, Long> unmapped(TracePipeline now) {
        if (unmapped.isEmpty()) {
            return now.unmapped();
        }
        UnmappedCounts all = new UnmappedCounts();
        all.addAll(unmapped.toMap());
        all.addAll(now.unmapped());
        return all.toMap();
    }
}
