package dev.predmon.pipeline;

import com.fasterxml.jackson.annotation.JsonValue;

import java.nio.file.Path;

/**
 * One run of a log: the log and the run's number in it (0, 1, 2, ... as the monitor counts them). Written as the log
 * alone for a log of one run, else {@code log#k}, in reports, JSON and messages alike; never read back from that text.
 *
 * @param log     the log file
 * @param run     the run's number in the log
 * @param several whether the log holds several runs (then the name carries the number)
 */
public record RunId(Path log, int run, boolean several) {

    /** Run {@code run} of {@code log}, a log of {@code runs} runs. */
    public static RunId of(Path log, int run, int runs) {
        return new RunId(log, run, runs > 1);
    }

    /** The run's name: {@code log}, or {@code log#k} in a log of several runs. */
    @JsonValue
    public String name() {
        return several ? log + "#" + run : log.toString();
    }

    /** The run's number when its log holds several, else null. */
    public Integer numberIfSeveral() {
        return several ? run : null;
    }

    @Override
    public String toString() {
        return name();
    }
}
