package dev.predmon.cli;

import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.watch.ExitRule;

import java.util.stream.IntStream;

/**
 * Exit codes of every predmon command (the README's table; BadInputCliTest checks every row). How watch, classify and
 * explain turn a judged log into 0, 1, 5 or 6 is {@link ExitRule}'s.
 */
public final class ExitCodes {
    /** Success; watch/classify/explain: no warning and a model still matches; verify: a machine matches. */
    public static final int OK = ExitRule.OK;
    /** watch/classify/explain: a warning (the run is predicted faulty); verify: the log does not match. */
    public static final int WARNING = ExitRule.WARNING;
    /** Bad usage: unknown option, missing argument, impossible value (picocli's own code). */
    public static final int USAGE = 2;
    /**
     * Bad input: a log, model directory, abstraction or scenario file that cannot be used, or a log with nothing to
     * judge; or an output that may not be replaced or could not be written completely (docs/reliability.md).
     */
    public static final int BAD_INPUT = ExitRule.BAD_INPUT;
    /** A bug in predmon; rerun with --verbose for the stack trace. */
    public static final int INTERNAL = 4;
    /** watch/classify/explain: no learned model matches the run (unknown behaviour): no prediction either way. */
    public static final int NO_MATCH = ExitRule.NO_MATCH;
    /** watch/classify/explain: a property was violated and no warning of any property came before it. */
    public static final int UNWARNED_VIOLATION = ExitRule.UNWARNED_VIOLATION;

    private ExitCodes() {
    }

    /** {@link ExitRule#of(boolean, boolean, boolean)}. */
    static int of(boolean unwarnedViolation, boolean noModelMatches, boolean warned) {
        return ExitRule.of(unwarnedViolation, noModelMatches, warned);
    }

    /** Watch's code for a log judged to its end ({@link ExitRule#ofMonitor}); classify gives the same. */
    static int ofMonitor(PredictiveMonitor m) {
        return ExitRule.ofMonitor(m);
    }

    /** {@link ExitRule#ofRuns(IntStream)}. */
    static int ofRuns(IntStream runCodes) {
        return ExitRule.ofRuns(runCodes);
    }
}
