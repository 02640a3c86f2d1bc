package dev.predmon.replay;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.parse.ParseProblem;
import dev.predmon.pipeline.Evidence;

import java.nio.file.Path;
import java.util.List;

/**
 * A log replayed to its end.
 *
 * @param log      the file
 * @param runs     every run the log holds, in order
 * @param problems what the parser could not read, in line order
 * @param lines    the lines of the file
 * @param monitor  the monitor that took it, at the end of the input (its summary gives watch's verdict)
 */
public record ReplayedLog(Path log, List<ReplayedRun> runs, List<ParseProblem> problems, long lines,
                          PredictiveMonitor monitor) {

    public ReplayedLog {
        runs = List.copyOf(runs);
        problems = List.copyOf(problems);
    }

    /** What the log gives to judge it by, as {@code watch} sees it at the end of the file. */
    public Evidence evidence(Abstraction abstraction) {
        return new Evidence(log, () -> lines, monitor.records(), monitor.interfaceRecords(), monitor.summary().pairs(),
                monitor.unmapped(), abstraction, problems.isEmpty() ? null : problems.get(0),
                monitor.pipeline().span());
    }

    /** Records read from the log. */
    public long records() {
        return monitor.pipeline().records();
    }

    /** What the log's times count ({@code s}, or ticks in a log without time stamps). */
    public String unit() {
        return monitor.clock().unit();
    }
}
