package dev.predmon.cli;

import dev.predmon.Terminal;
import dev.predmon.parse.ParseProblem;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.watch.ProblemLines;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/** Prints what reading a log found wrong with it, one line each, on stderr. */
final class Problems {

    private Problems() {
    }

    /**
     * The parse problems of a log that gave evidence, then the interface messages no rule maps
     * ({@link ProblemLines#unmapped}).
     */
    static void print(PrintWriter err, Path log, LogTrace trace) {
        print(err, log, trace.problems(), trace.unmapped());
    }

    /** As above, of a log's {@code problems} and {@code unmapped} messages. */
    static void print(PrintWriter err, Path log, List<ParseProblem> problems, Map<String, Long> unmapped) {
        problems.forEach(p -> err.println(Terminal.line(p.format(log.toString()))));
        ProblemLines.unmapped(err, log, unmapped);
    }
}
