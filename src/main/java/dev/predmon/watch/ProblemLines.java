package dev.predmon.watch;

import dev.predmon.Terminal;
import dev.predmon.parse.ParseProblem;
import dev.predmon.pipeline.Traces;
import dev.predmon.pipeline.UnmappedMessages;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * One log's parse problems on stderr, one line each: at once while following; with {@code --no-follow} held until the
 * log is known to hold something to judge (so that a file that is no log gets one line, not a list), the first
 * {@value Traces#MAX_PROBLEMS} of them, the rest counted.
 */
public final class ProblemLines {

    private final List<ParseProblem> held = new ArrayList<>();
    private long more;
    private ParseProblem first;

    /** Takes {@code p} of {@code log}: printed on {@code err} at once, or held when {@code hold}. */
    void add(PrintWriter err, String log, ParseProblem p, boolean hold) {
        if (first == null) {
            first = p;
        }
        if (!hold) {
            err.println(Terminal.line(p.format(log)));
            err.flush();
        } else if (held.size() < Traces.MAX_PROBLEMS) {
            held.add(p);
        } else {
            more++;
        }
    }

    /** Prints the problems held, and how many more there were. */
    void flush(PrintWriter err, String log) {
        held.forEach(p -> err.println(Terminal.line(p.format(log))));
        if (more > 0) {
            err.println(Terminal.line(log) + ": " + more + " more problem(s) not shown");
        }
        held.clear();
        err.flush();
    }

    /** The log's first problem, or null: what a file that is no log is judged by. */
    ParseProblem first() {
        return first;
    }

    /**
     * The interface messages no abstraction rule maps, never silently dropped: one line per command with its count
     * and why, at most {@value UnmappedMessages#MAX_LINES} lines (a pose a message would be a line per value).
     */
    public static void unmapped(PrintWriter err, Path log, Map<String, Long> unmapped) {
        UnmappedMessages.lines(unmapped).forEach(line -> err.println(Terminal.line(log + ": warning: interface "
                + "messages no rule maps: " + line)));
        err.flush();
    }
}
