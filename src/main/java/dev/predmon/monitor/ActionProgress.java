package dev.predmon.monitor;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.property.UnderWay;

import java.util.Arrays;
import java.util.List;

/**
 * Whether the safety property's recommended action is under way in the run: one of the abstraction's
 * {@link UnderWay} messages started it and nothing since stopped it (each message its own way: a skill by its
 * {@code send_stop}, a command by the same command going elsewhere). Holds one flag per message.
 */
final class ActionProgress {

    private final List<UnderWay> messages;
    private final boolean[] active;
    private double since = Double.NaN;
    private long sinceLine;

    ActionProgress(List<UnderWay> messages) {
        this.messages = List.copyOf(messages);
        this.active = new boolean[this.messages.size()];
    }

    /**
     * Takes a record of the run; returns the message that started the action, or stopped it (then {@link #underWay}
     * is false), when this record changed whether it is under way; else null.
     */
    UnderWay record(LogRecord r) {
        if (r.kind() != RecordKind.COMMAND) {
            return null; // only a command starts or stops an action (UnderWay#starts, #ends)
        }
        boolean before = underWay();
        UnderWay changed = null;
        for (int i = 0; i < messages.size(); i++) {
            UnderWay m = messages.get(i);
            if (!active[i] && m.starts(r)) {
                active[i] = true;
                changed = m;
            } else if (active[i] && m.ends(r)) {
                active[i] = false;
                changed = changed == null ? m : changed;
            }
        }
        boolean now = underWay();
        if (now && !before) {
            since = r.time();
            sinceLine = r.line();
        }
        return now != before ? changed : null;
    }

    /** Whether the action is under way now. */
    boolean underWay() {
        for (boolean a : active) {
            if (a) {
                return true;
            }
        }
        return false;
    }

    /** When it became under way (the log's time), NaN if never in this run. */
    double since() {
        return since;
    }

    /** The line at which it became under way, 0 if never in this run. */
    long sinceLine() {
        return sinceLine;
    }

    /** A new run: nothing is under way. */
    void reset() {
        Arrays.fill(active, false);
        since = Double.NaN;
        sinceLine = 0;
    }
}
