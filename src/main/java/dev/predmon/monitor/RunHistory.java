package dev.predmon.monitor;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The outcomes of the runs a monitor has finished, in bounded memory: the latest {@link #KEPT} in full, and over all
 * of them since the start what the log's verdict needs (how many, their pairs, the first warned, whether any lost
 * every model or observed the property). A watch that follows a robot for months, a run every few minutes, stays
 * the same size.
 */
final class RunHistory {

    /** Finished runs whose outcome is kept in full; older ones only count. */
    static final int KEPT = 1000;

    private final ArrayDeque<RunOutcome> latest = new ArrayDeque<>();
    private int count;
    private long pairs;
    private boolean noMatch;
    private boolean safetyObserved;
    private boolean warnedMatching;
    private RunOutcome firstWarned;

    /** A run has finished with {@code outcome}. */
    void add(RunOutcome outcome) {
        count++;
        pairs += outcome.pairs();
        noMatch |= outcome.noMatch();
        safetyObserved |= outcome.safetyObserved();
        warnedMatching |= outcome.warning() != null && !outcome.noMatch();
        if (firstWarned == null && outcome.warning() != null) {
            firstWarned = outcome;
        }
        latest.addLast(outcome);
        if (latest.size() > KEPT) {
            latest.removeFirst();
        }
    }

    /** Runs finished since the start. */
    int count() {
        return count;
    }

    /** Finished runs whose outcome is no longer kept in full. */
    int dropped() {
        return count - latest.size();
    }

    /** The kept outcomes, oldest first, then {@code current}. */
    List<RunOutcome> withCurrent(RunOutcome current) {
        List<RunOutcome> all = new ArrayList<>(latest);
        all.add(current);
        return List.copyOf(all);
    }

    /** The summary of the finished runs and {@code current}. */
    RunsSummary summary(RunOutcome current) {
        RunOutcome warned = firstWarned != null || current.warning() == null ? firstWarned : current;
        return new RunsSummary(count + 1, dropped(), pairs + current.pairs(), noMatch || current.noMatch(),
                safetyObserved || current.safetyObserved(),
                warnedMatching || (current.warning() != null && !current.noMatch()), Optional.ofNullable(warned));
    }
}
