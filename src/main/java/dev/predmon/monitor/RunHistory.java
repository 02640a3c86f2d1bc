package dev.predmon.monitor;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The outcomes of the runs a monitor has finished, in bounded memory: the latest {@link #KEPT} in full, and over all
 * of them since the start what the log's verdict needs (how many, their pairs, the first warned, whether any lost
 * every model, were warned, observed a property or violated one unwarned). A watch that follows a robot for months, a run every
 * few minutes, stays the same size.
 */
final class RunHistory {

    /** Finished runs whose outcome is kept in full; older ones only count. */
    static final int KEPT = 1000;

    private final ArrayDeque<RunOutcome> latest = new ArrayDeque<>();
    private Totals finished = Totals.NONE;

    /** What a number of runs add up to; {@link #plus} counts one more. */
    private record Totals(int count, long pairs, boolean noMatch, boolean safetyObserved, boolean warnedMatching,
                          RunOutcome firstWarned, boolean unwarnedViolation, boolean warned) {

        static final Totals NONE = new Totals(0, 0, false, false, false, null, false, false);

        Totals plus(RunOutcome o) {
            return new Totals(count + 1, pairs + o.pairs(), noMatch || o.noMatch(),
                    safetyObserved || o.safetyObserved(), warnedMatching || (o.warned() && !o.noMatch()),
                    firstWarned != null || o.warning() == null ? firstWarned : o,
                    unwarnedViolation || o.unwarnedViolation(), warned || o.warned());
        }
    }

    /** A run has finished with {@code outcome}. */
    void add(RunOutcome outcome) {
        finished = finished.plus(outcome);
        latest.addLast(outcome);
        if (latest.size() > KEPT) {
            latest.removeFirst();
        }
    }

    /** Runs finished since the start. */
    int count() {
        return finished.count();
    }

    /** Whether in a finished run a point came where no model matched. */
    boolean noMatch() {
        return finished.noMatch();
    }

    /** Finished runs whose outcome is no longer kept in full. */
    int dropped() {
        return finished.count() - latest.size();
    }

    /** The kept outcomes, oldest first, then {@code current}. */
    List<RunOutcome> withCurrent(RunOutcome current) {
        List<RunOutcome> all = new ArrayList<>(latest);
        all.add(current);
        return List.copyOf(all);
    }

    /** The summary of the finished runs and {@code current}. */
    RunsSummary summary(RunOutcome current) {
        Totals all = finished.plus(current);
        return new RunsSummary(all.count(), dropped(), all.pairs(), all.noMatch(), all.safetyObserved(),
                all.warnedMatching(), Optional.ofNullable(all.firstWarned()), all.unwarnedViolation(),
                all.warned());
    }
}
