package dev.predmon.replay;

import dev.predmon.monitor.PredictiveMonitor;

import java.nio.file.Path;
import java.util.List;

/**
 * A log replayed to its end.
 *
 * @param log      the file
 * @param runs     every run the log holds, in order
 * @param problems the lines the parser could not read
 * @param monitor  the monitor that took it, at the end of the input (its summary gives watch's verdict)
 */
public record ReplayedLog(Path log, List<ReplayedRun> runs, int problems, PredictiveMonitor monitor) {

    public ReplayedLog {
        runs = List.copyOf(runs);
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
