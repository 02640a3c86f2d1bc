package dev.predmon.pipeline;

import java.util.Collections;
import java.util.Map;
import java.util.TreeMap;

/**
 * How many interface messages of each kind no rule maps, in bounded memory. A kind names its value
 * ({@code GoTo/getCurrentPose reply '-6.19;0.55'}), so a log read for months by the wrong abstraction has a kind per
 * reading; as the run history keeps the latest runs in full and only counts the others, this keeps the first
 * {@value #KINDS} kinds apart and counts each later new kind under its command ({@code GoTo/getCurrentPose}
 * {@value #OTHER}), for at most {@value #KINDS} commands, then under {@value #OTHER_COMMANDS}. Every message is
 * counted.
 */
public final class UnmappedCounts {

    /** Kinds told apart; as many commands again are counted as a whole beyond them. */
    public static final int KINDS = 1000;
    /** The end of the key that counts a command's kinds beyond {@link #KINDS}. */
    public static final String OTHER = "(other values)";
    /** The key that counts every message beyond both bounds. */
    public static final String OTHER_COMMANDS = "(other commands)";

    private final Map<String, Long> counts = new TreeMap<>();
    private int kinds;
    private int commands;

    /**
     * Counts {@code n} messages of {@code kind}.
     *
     * @return the key they were counted under, or null when that key was counted before
     */
    public String add(String kind, long n) {
        String key = keyOf(kind);
        Long before = counts.merge(key, n, Long::sum) - n;
        if (before != 0) {
            return null;
        }
        if (key.endsWith(" " + OTHER)) {
            commands++;
        } else if (!key.equals(OTHER_COMMANDS)) {
            kinds++;
        }
        return key;
    }

    /** Adds every count of {@code other}. */
    public void addAll(Map<String, Long> other) {
        other.forEach(this::add);
    }

    private String keyOf(String kind) {
        if (counts.containsKey(kind)) {
            return kind;
        }
        boolean folded = kind.equals(OTHER_COMMANDS) || kind.endsWith(" " + OTHER);
        if (!folded && kinds < KINDS) {
            return kind;
        }
        if (kind.equals(OTHER_COMMANDS)) {
            return kind;
        }
        String byCommand = UnmappedMessages.command(kind) + " " + OTHER;
        return counts.containsKey(byCommand) || commands < KINDS ? byCommand : OTHER_COMMANDS;
    }

    public void clear() {
        counts.clear();
        kinds = 0;
        commands = 0;
    }

    public boolean isEmpty() {
        return counts.isEmpty();
    }

    /** A sorted copy of the counts by key. */
    public Map<String, Long> toMap() {
        return Collections.unmodifiableMap(new TreeMap<>(counts));
    }
}
