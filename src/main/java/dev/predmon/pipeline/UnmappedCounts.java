package dev.predmon.pipeline;

import dev.predmon.abstraction.UnmappedMessage;

import java.util.Collections;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;

/**
 * How many interface messages of each kind no rule maps, in bounded memory. A kind names its value
 * ({@code GoTo/getCurrentPose reply '-6.19;0.55'}), so a log read for months by the wrong abstraction has a kind per
 * reading; as the run history keeps the latest runs in full and only counts the others, this keeps the first
 * {@value #KINDS} kinds apart and counts each later new kind under its command ({@code GoTo/getCurrentPose}
 * {@value UnmappedMessage#OTHER}), for at most {@value #KINDS} commands, then under
 * {@link UnmappedMessage#OTHER_COMMANDS}. Every message is counted.
 */
public final class UnmappedCounts {

    /** Kinds told apart; as many commands again are counted as a whole beyond them. */
    public static final int KINDS = 1000;

    private final Map<UnmappedMessage, Long> counts = new HashMap<>();
    private int kinds;
    private int commands;

    /**
     * Counts {@code n} messages of {@code kind}.
     *
     * @return the kind they were counted under, or null when that kind was counted before
     */
    public UnmappedMessage add(UnmappedMessage kind, long n) {
        UnmappedMessage key = keyOf(kind);
        long before = counts.merge(key, n, Long::sum) - n;
        if (before != 0) {
            return null;
        }
        if (key.kind() == UnmappedMessage.Kind.OTHER_VALUES) {
            commands++;
        } else if (key.kind() != UnmappedMessage.Kind.OTHER_COMMANDS) {
            kinds++;
        }
        return key;
    }

    /** Adds every count of {@code other}. */
    public void addAll(Map<UnmappedMessage, Long> other) {
        other.forEach(this::add);
    }

    private UnmappedMessage keyOf(UnmappedMessage kind) {
        if (counts.containsKey(kind)) {
            return kind;
        }
        UnmappedMessage.Kind k = kind.kind();
        if (k == UnmappedMessage.Kind.OTHER_COMMANDS) {
            return kind;
        }
        if (k != UnmappedMessage.Kind.OTHER_VALUES && kinds < KINDS) {
            return kind;
        }
        UnmappedMessage byCommand = UnmappedMessage.otherValues(kind);
        return counts.containsKey(byCommand) || commands < KINDS ? byCommand : UnmappedMessage.OTHER_COMMANDS;
    }

    public void clear() {
        counts.clear();
        kinds = 0;
        commands = 0;
    }

    public boolean isEmpty() {
        return counts.isEmpty();
    }

    /** A copy of the counts by kind, in the order of the kinds' texts. */
    public Map<UnmappedMessage, Long> toMap() {
        return Collections.unmodifiableMap(new TreeMap<>(counts));
    }
}
