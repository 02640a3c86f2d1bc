package dev.predmon.cli;

import dev.predmon.parse.ParseProblem;
import dev.predmon.pipeline.Traces;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;

/**
 * One log's parse problems on stderr, one line each: at once while following; with {@code --no-follow} held until the
 * log is known to hold something to judge (so that a file that is no log gets one line, not a list), the first
 * {@value Traces#MAX_PROBLEMS} of them, the rest counted.
 */
final class ProblemLines {

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
}
