package dev.predmon.watch;

import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.RunsSummary;

import java.util.Arrays;
import java.util.List;
import java.util.stream.IntStream;

/**
 * The one rule by which watch, classify and explain turn what the monitor saw into an exit code, over every property
 * of the abstraction (the README's table; ExitCodeTableTest runs every row).
 */
public final class ExitRule {
    /** No warning, no violation, and a nominal model matches the run. */
    public static final int OK = 0;
    /** A warning of some property (the run is predicted faulty), and no violation before it. */
    public static final int WARNING = 1;
    /** A log with nothing to judge, or one that cannot be read. */
    public static final int BAD_INPUT = 3;
    /** No learned model matches the run (unknown behaviour): no prediction either way. */
    public static final int NO_MATCH = 5;
    /**
     * Some property was violated and no warning of any property came before it (a missed run; a warning at or after
     * the violation predicts nothing). It wins over every other verdict: it is the one a script must not miss.
     */
    public static final int UNWARNED_VIOLATION = 6;

    private ExitRule() {
    }

    /**
     * A judged run's code: a violation no warning came before ({@link #UNWARNED_VIOLATION}); else from which models
     * still match the run at the end: none ({@link #NO_MATCH}, whatever came before), only faulty ones or a warning
     * ({@link #WARNING}), or a nominal one ({@link #OK}).
     *
     * @param unwarnedViolation some property was violated with no warning of any property before it
     * @param noModelMatches    no model, nominal or faulty, matches the run
     * @param warned            a warning of some property was raised
     */
    public static int of(boolean unwarnedViolation, boolean noModelMatches, boolean warned) {
        return unwarnedViolation ? UNWARNED_VIOLATION : noModelMatches ? NO_MATCH : warned ? WARNING : OK;
    }

    /**
     * The code of a log judged to its end: its run's {@link #of} code, or for a log of several runs the first of
     * {@link #UNWARNED_VIOLATION}, {@link #WARNING}, {@link #NO_MATCH} and {@link #OK} that one of its runs has.
     * {@code classify} and {@code explain} give the same, from the same replay.
     */
    public static int ofMonitor(PredictiveMonitor m) {
        RunsSummary all = m.summary();
        return all.runs() == 1 ? of(all.unwarnedViolation(), all.noMatch(), all.warned())
                : ofRuns(all.unwarnedViolation(), all.warnedMatching(), all.noMatch());
    }

    /** The code of several runs or logs, from each one's code: the first of 6, 1, 5 and 0 that one of them has. */
    public static int ofRuns(IntStream codes) {
        int[] c = codes.toArray();
        return ofRuns(Arrays.stream(c).anyMatch(x -> x == UNWARNED_VIOLATION),
                Arrays.stream(c).anyMatch(x -> x == WARNING), Arrays.stream(c).anyMatch(x -> x == NO_MATCH));
    }

    private static int ofRuns(boolean unwarnedViolation, boolean warnedMatching, boolean noMatch) {
        return unwarnedViolation ? UNWARNED_VIOLATION : warnedMatching ? WARNING : noMatch ? NO_MATCH : OK;
    }

    /**
     * The code of several logs ({@code watch} with several), from each log's code: as {@link #ofRuns(IntStream)}, and
     * only when no log held anything to judge, {@link #BAD_INPUT}.
     */
    public static int ofLogs(List<Integer> codes) {
        if (codes.stream().noneMatch(c -> c == OK || c == WARNING || c == NO_MATCH || c == UNWARNED_VIOLATION)) {
            return BAD_INPUT;
        }
        return ofRuns(codes.stream().mapToInt(Integer::intValue));
    }
}
