package dev.predmon.cli;

import dev.predmon.pipeline.LogTrace;

import java.io.PrintWriter;
import java.nio.file.Path;

/** Prints what reading a log found wrong with it, one line each, on stderr. */
final class Problems {

    private Problems() {
    }

    static void print(PrintWriter err, Path log, LogTrace trace) {
        trace.problems().forEach(p -> err.println(p.format(log.toString())));
        if (trace.interfaceRecords() == 0) {
            err.println(log + ": warning: no skill-component interface message in " + trace.records()
                    + " records; is this a YARP monitor log of the case study?");
        }
        trace.unmapped().forEach((k, n) -> err.println(log + ": warning: " + n + " interface message(s) no rule maps: " + k));
        err.flush();
    }
}
