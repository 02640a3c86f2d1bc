package dev.predmon.cli;

import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.RunsSummary;

import java.util.Arrays;
import java.util.List;
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
    /**
     * watch/classify/explain: the property was violated and no warning came before it (a missed run; a warning at
     * or after the violation predicts nothing). It wins over every other verdict: it is the one a script must not miss.
     */
    public static final int UNWARNED_VIOLATION = 6;

    private ExitCodes() {
    }

    /**
     * The one rule by which watch, classify and explain turn a judged run into an exit code: a violation no warning
     * came before ({@link #UNWARNED_VIOLATION}); else from which models still match the run at the end: none
     * ({@link #NO_MATCH}, whatever came before), only faulty ones (a warning, {@link #WARNING}), or a nominal one
     * ({@link #OK}).
     *
     * @param unwarnedViolation the property was violated with no warning before it
     * @param noModelMatches    no model, nominal or faulty, matches the run
     * @param warned            every nominal model is out while a faulty one matched
     */
    static int of(boolean unwarnedViolation, boolean noModelMatches, boolean warned) {
        return unwarnedViolation ? UNWARNED_VIOLATION : noModelMatches ? NO_MATCH : warned ? WARNING : OK;
    }

    /**
     * The code of a log that holds several runs, from each run's {@link #of} code: a violation no warning came
     * before, in any run, is the log's; else a warning in any run; else a run that no model matched makes it
     * {@link #NO_MATCH}; else {@link #OK}.
     */
    static int ofRuns(RunsSummary runs) {
        return ofRuns(runs.unwarnedViolation(), runs.warnedMatching(), runs.noMatch());
    }

    /**
     * Watch's code for a log {@code m} judged to its end: the run's {@link #of} code, or {@link #ofRuns(RunsSummary)}
     * for a log of several runs. {@code classify} gives the same, from the same replay.
     */
    static int ofMonitor(PredictiveMonitor m) {
        RunsSummary all = m.summary();
        return all.runs() == 1 ? of(all.unwarnedViolation(), all.noMatch(), all.warned()) : ofRuns(all);
    }

    /** {@link #ofRuns(RunsSummary)} from each run's {@link #of} code. */
    static int ofRuns(IntStream runCodes) {
        int[] codes = runCodes.toArray();
        return ofRuns(Arrays.stream(codes).anyMatch(c -> c == UNWARNED_VIOLATION),
                Arrays.stream(codes).anyMatch(c -> c == WARNING), Arrays.stream(codes).anyMatch(c -> c == NO_MATCH));
    }

    /**
     * The code of several judged runs or logs ({@code watch} with several logs): the first of
     * {@link #UNWARNED_VIOLATION}, {@link #WARNING}, {@link #NO_MATCH} and {@link #OK} that one of them has.
     */
    private static int ofRuns(boolean unwarnedViolation, boolean warnedMatching, boolean noMatch) {
        return unwarnedViolation ? UNWARNED_VIOLATION : warnedMatching ? WARNING : noMatch ? NO_MATCH : OK;
    }

    /**
     * The code of several logs, from each log's code: as {@link #ofRuns(IntStream)}, and only when no log held
     * anything to judge, {@link #BAD_INPUT}.
     */
    static int ofLogs(List<Integer> codes) {
        if (codes.stream().noneMatch(c -> c == OK || c == WARNING || c == NO_MATCH || c == UNWARNED_VIOLATION)) {
            return BAD_INPUT;
        }
        return ofRuns(codes.stream().mapToInt(Integer::intValue));
    }
}
