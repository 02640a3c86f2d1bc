package dev.predmon.monitor;

import dev.predmon.pipeline.TracePipeline;

import java.util.Map;
import java.util.TreeMap;

/**
 * What a log's pipeline counted before its restarts. The pipeline counts from 0 again after a truncation or
 * replacement, as it reads a new file; what {@code watch} reports at its end counts everything since it started.
 */
final class LogTotals {

    private long records;
    private long interfaceRecords;
    private final Map<String, Long> unmapped = new TreeMap<>();

    /** Adds what {@code pipeline} counted, just before it is reset. */
    void add(TracePipeline pipeline) {
        records += pipeline.records();
        interfaceRecords += pipeline.interfaceRecords();
        pipeline.unmapped().forEach((k, n) -> unmapped.merge(k, n, Long::sum));
    }

    long records(TracePipeline now) {
        return records + now.records();
    }

    long interfaceRecords(TracePipeline now) {
        return interfaceRecords + now.interfaceRecords();
    }

    Map<String, Long> unmapped(TracePipeline now) {
        Map<String, Long> all = new TreeMap<>(unmapped);
        now.unmapped().forEach((k, n) -> all.merge(k, n, Long::sum));
        return all;
    }
}
