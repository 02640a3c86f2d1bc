package dev.predmon.pipeline;

import dev.predmon.abstraction.Classification;
import dev.predmon.abstraction.Direction;
import dev.predmon.abstraction.RunRule;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;

import java.util.ArrayList;
import java.util.List;

/**
 * Finds where the tree starts over in a log without ticks: after a quiet pause, the interface begins again the way
 * the log began (its first two distinct commands, in order). Records after such a pause are held back until the
 * commands decide, a few records later, so that a new run gets its first pair.
 *
 * <p>A pause is quiet when it lasts at least {@link RunRule#quiet()} seconds and
 * {@link #PACE} times the run's mean gap between records: a log that records every ten seconds pauses ten seconds all
 * the time. A paused tree that goes on (a blocking call, a robot waiting) does not start with the log's first two
 * commands, so it does not split.
 */
final class QuietRestart {

    /** How many mean gaps a pause must last. */
    static final double PACE = 20.0;
    /** Records a run must have before its pace is trusted. */
    static final long MIN_RECORDS = 10;
    /** Records held at most while the commands decide; past this the pause was not a restart. */
    static final int MAX_HELD = 256;

    /** What the held records say. */
    enum Decision { PENDING, RESTART, SAME_RUN }

    private final double quiet;
    private String first;
    private String second;
    private long timed;
    private double runStart = Double.NaN;
    private double lastTime = Double.NaN;
    private final List<LogRecord> held = new ArrayList<>();
    private final List<Classification> heldAs = new ArrayList<>();
    private final List<Boolean> heldStarts = new ArrayList<>();
    private boolean sawFirst;

    /** @param quiet the shortest pause in seconds, 0 for off */
    QuietRestart(double quiet) {
        this.quiet = quiet;
    }

    /** Whether {@code r} comes after a quiet pause of a run that logged enough to know its pace. */
    boolean quietBefore(LogRecord r) {
        if (quiet <= 0 || r.clock() != Clock.SECONDS || Double.isNaN(r.time()) || Double.isNaN(lastTime)
                || timed < MIN_RECORDS || first == null) {
            return false;
        }
        double gap = r.time() - lastTime;
        return gap >= quiet && gap >= PACE * (lastTime - runStart) / (timed - 1);
    }

    /** Whether records are held back. */
    boolean holding() {
        return !held.isEmpty();
    }

    /** Holds {@code r} ({@code starts}: another rule starts a run at it) and says whether the commands decided. */
    Decision hold(LogRecord r, Classification c, boolean starts) {
        held.add(r);
        heldAs.add(c);
        heldStarts.add(starts);
        if (starts) {
            return Decision.SAME_RUN; // another rule decides; the held records before it stay in the run
        }
        if (held.size() >= MAX_HELD) {
            return Decision.SAME_RUN;
        }
        if (!(c instanceof Classification.Mapped m) || m.event().direction() != Direction.INPUT) {
            return Decision.PENDING;
        }
        String s = m.event().symbol();
        if (!sawFirst) {
            if (!s.equals(first)) {
                return Decision.SAME_RUN;
            }
            sawFirst = true;
            return second == null ? Decision.RESTART : Decision.PENDING;
        }
        if (s.equals(first)) {
            return Decision.PENDING;
        }
        return s.equals(second) ? Decision.RESTART : Decision.SAME_RUN;
    }

    /** The held records, their classifications and whether another rule started a run at each; then none is held. */
    List<Held> release() {
        List<Held> out = new ArrayList<>();
        for (int i = 0; i < held.size(); i++) {
            out.add(new Held(held.get(i), heldAs.get(i), heldStarts.get(i)));
        }
        held.clear();
        heldAs.clear();
        heldStarts.clear();
        sawFirst = false;
        return out;
    }

    /** A record held back. */
    record Held(LogRecord record, Classification classification, boolean starts) {
    }

    /** Takes a record as processed: its time sets the pace, the log's first commands are remembered. */
    void processed(LogRecord r, Classification c, boolean startsRun) {
        if (startsRun) {
            timed = 0;
        }
        if (!Double.isNaN(r.time())) {
            if (timed++ == 0) {
                runStart = r.time();
            }
            lastTime = Double.isNaN(lastTime) ? r.time() : Math.max(lastTime, r.time());
        }
        if (second == null && c instanceof Classification.Mapped m && m.event().direction() == Direction.INPUT) {
            String s = m.event().symbol();
            if (first == null) {
                first = s;
            } else if (!s.equals(first)) {
                second = s;
            }
        }
    }

    void reset() {
        first = null;
        second = null;
        timed = 0;
        runStart = Double.NaN;
        lastTime = Double.NaN;
        release();
    }
}
