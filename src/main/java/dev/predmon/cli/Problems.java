package dev.predmon.cli;

import dev.predmon.pipeline.LogTrace;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Map;

/** Prints what reading a log found wrong with it, one line each, on stderr. */
final class Problems {

    private Problems() {
    }

    static void print(PrintWriter err, Path log, LogTrace trace) {
        trace.problems().forEach(p -> err.println(p.format(log.toString())));
        interfaceMessages(err, log, trace.records(), trace.interfaceRecords(), trace.unmapped());
    }

    /**
     * What the abstraction could not use: when it mapped nothing, one line saying so (a verdict on an unmonitored
     * log would be silently wrong), else one line per kind of interface message no rule maps.
     */
    static void interfaceMessages(PrintWriter err, Path log, long records, long interfaceRecords,
                                  Map<String, Long> unmapped) {
        long mapped = interfaceRecords - unmapped.values().stream().mapToLong(Long::longValue).sum();
        if (mapped == 0) {
            err.println(log + ": warning: no skill-component interface message the abstraction maps in "
                    + records + " records" + (unmapped.isEmpty() ? "" : " (only "
                    + String.join(", ", unmapped.keySet().stream().limit(3).toList())
                    + (unmapped.size() > 3 ? ", ..." : "") + ")")
                    + "; is this a YARP monitor log of the case study, and the right --abstraction?");
        } else {
            unmapped.forEach((k, n) -> err.println(log + ": warning: " + n + " interface message(s) no rule maps: " + k));
        }
        err.flush();
    }
}
