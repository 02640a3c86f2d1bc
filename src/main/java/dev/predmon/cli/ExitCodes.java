package dev.predmon.cli;

import dev.predmon.monitor.RunsSummary;

import java.util.Arrays;
import java.util.stream.IntStream;

/** Exit codes of every predmon command (the README's table; BadInputCliTest checks every row). */
public final class ExitCodes {
    /** Success; watch/classify/explain: no warning and a model still matches; verify: a machine matches. */
    public static final int OK = 0;
    /** watch/classify/explain: a warning (the run is predicted faulty); verify: the log does not match. */
    public static final int WARNING = 1;
    /** Bad usage: unknown option, missing argument, impossible value (picocli's own code). */
    public static final int USAGE = 2;
    /**
     * Bad input: a log, model directory, abstraction or scenario file that cannot be used, or a log with nothing to
     * judge; or an output that may not be replaced or could not be written completely (docs/reliability.md).
     */
    public static final int BAD_INPUT = 3;
    /** A bug in predmon; rerun with --verbose for the stack trace. */
    public static final int INTERNAL = 4;
    /** watch/classify/explain: no learned model matches the run (unknown behaviour): no prediction either way. */
    public static final int NO_MATCH = 5;

    private ExitCodes() {
    }

    /**
     * The one rule by which watch, classify and explain turn a judged run into an exit code, from which models
     * still match it at the end: none ({@link #NO_MATCH}, whatever came before), only faulty ones (a warning,
     * {@link #WARNING}), or a nominal one ({@link #OK}).
     *
     * @param noModelMatches no model, nominal or faulty, matches the run
     * @param warned         every nominal model is out while a faulty one matched
     */
    static int of(boolean noModelMatches, boolean warned) {
        return noModelMatches ? NO_MATCH : warned ? WARNING : OK;
    }

    /**
     * The code of a log that holds several runs, from each run's {@link #of} code: a warning in any run is the log's
     * warning; else a run that no model matched makes it {@link #NO_MATCH}; else {@link #OK}.
     */
    static int ofRuns(RunsSummary runs) {
        return ofRuns(runs.warnedMatching(), runs.noMatch());
    }

    /** {@link #ofRuns(RunsSummary)} from each run's {@link #of} code. */
    static int ofRuns(IntStream runCodes) {
        int[] codes = runCodes.toArray();
        return ofRuns(Arrays.stream(codes).anyMatch(c -> c == WARNING),
                Arrays.stream(codes).anyMatch(c -> c == NO_MATCH));
    }

    /** The log's code: a run warned while a model still matched it wins over a run no model matched. */
    private static int ofRuns(boolean warnedMatching, boolean noMatch) {
        return warnedMatching ? WARNING : noMatch ? NO_MATCH : OK;
    }
}
