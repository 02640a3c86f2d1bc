package dev.predmon.cli;

import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.UnmappedMessages;

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

    /**
     * The interface messages no abstraction rule maps, never silently dropped: one line per command with its count
     * and why, at most {@value UnmappedMessages#MAX_LINES} lines (a pose a message would be a line per value).
     */
    static void unmapped(PrintWriter err, Path log, Map<UnmappedMessage, Long> unmapped) {
        UnmappedMessages.lines(unmapped).forEach(line -> err.println(Terminal.line(log + ": warning: interface "
                + "messages no rule maps: " + line)));
        err.flush();
    }
}
