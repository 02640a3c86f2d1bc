package dev.predmon.cli;

import dev.predmon.pipeline.LogTrace;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Map;

/** Prints what reading a log found wrong with it, one line each, on stderr. */
final class Problems {

    private Problems() {
    }

    /** The parse problems of a log that gave evidence, then the interface messages no rule maps. */
    static void print(PrintWriter err, Path log, LogTrace trace) {
        trace.problems().forEach(p -> err.println(Terminal.line(p.format(log.toString()))));
        unmapped(err, log, trace.unmapped());
    }

    /** One line per kind of interface message no abstraction rule maps, with its count: never silently dropped. */
    static void unmapped(PrintWriter err, Path log, Map<String, Long> unmapped) {
        unmapped.forEach((k, n) -> err.println(Terminal.line(log + ": warning: " + n + " interface message(s) no rule maps: " + k)));
        err.flush();
    }
}
