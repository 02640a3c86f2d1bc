package dev.predmon.parse;

import java.util.Arrays;
import java.util.Locale;

/**
 * The record in progress: its header, the fields read so far, and which label comes next. Shared by every
 * layout, which differ only in how a record's header line looks and where its time comes from.
 *
 * <p>Two record shapes: the current one ({@code <Kind> intercepted:} then {@code From}, {@code To},
 * {@code Protocol}, {@code Command}, {@code Arguments}, {@code Reply}), and the older one ({@code Message
 * received:} then {@code From}, {@code To}, one of {@code Command}/{@code Reply}/{@code Tick} whose label is the
 * kind and whose value is the method, then {@code Arguments} holding all arguments and reply values).
 */
final class RecordDraft {
    private static final String[] CURRENT = {"From", "To", "Protocol", "Command", "Arguments", "Reply"};
    /** {@code null} stands for the kind label of the older layout: Command, Reply or Tick. */
    private static final String[] OLDER = {"From", "To", null, "Arguments"};

    long line;
    private double time;
    private String level;
    private String[] labels;
    private String[] values;
    private RecordKind kind;
    private int next;

    /** @param kindWord the {@code <Kind>} of a current header, {@code null} for {@code Message received:} */
    RecordDraft(long line, double time, String level, String kindWord) {
        this(line, time, level, kindWord == null ? null : RecordKind.valueOf(kindWord.toUpperCase(Locale.ROOT)));
    }

    /** @param kind the kind of a current header, {@code null} for {@code Message received:} */
    RecordDraft(long line, double time, String level, RecordKind kind) {
        this.line = line;
        this.time = time;
        this.level = level;
        this.labels = kind == null ? OLDER : CURRENT;
        this.values = new String[labels.length];
        this.kind = kind;
    }

    /**
     * This draft, emptied and started again as {@code new RecordDraft(line, time, level, kind)} would start: a
     * layout may reuse the draft of a record already built (its values are in the record, not in the draft).
     */
    RecordDraft restart(long line, double time, String level, RecordKind kind) {
        String[] wanted = kind == null ? OLDER : CURRENT;
        if (labels != wanted) {
            labels = wanted;
            values = new String[wanted.length];
        }
        this.line = line;
        this.time = time;
        this.level = level;
        this.kind = kind;
        this.next = 0;
        return this;
    }

    /** The index of the field expected next in the current shape (0 for From ... 5 for Reply), -1 in the older one. */
    int currentField() {
        return labels == CURRENT ? next : -1;
    }

    /** Whether the ASCII bytes are the label expected next (any case); false for the older kind line. */
    boolean expects(byte[] b, int offset, int len) {
        String wanted = labels[next];
        if (wanted == null || wanted.length() != len) {
            return false;
        }
        for (int i = 0; i < len; i++) {
            // Labels are ASCII letters (checked by the caller): folding bit 0x20 compares them case-blind.
            if ((b[offset + i] | 0x20) != (wanted.charAt(i) | 0x20)) {
                return false;
            }
        }
        return true;
    }

    /** Takes the value of the field expected next, its label already checked ({@link #expects}) and the value trimmed. */
    void take(String value) {
        values[next++] = value;
    }

    /** Takes the next field if {@code label} is the one expected; returns whether it was. */
    boolean offer(String label, String value) {
        String wanted = labels[next];
        if (wanted == null) {
            RecordKind labelled = olderKind(label);
            if (labelled == null) {
                return false;
            }
            kind = labelled;
        } else if (!wanted.equalsIgnoreCase(label)) {
            return false;
        }
        values[next++] = value;
        return true;
    }

    boolean complete() {
        return next == labels.length;
    }

    /** The label expected next, as the log writes it, for messages. */
    String expected() {
        String wanted = labels[next];
        return wanted == null ? "'Command :', 'Reply :' or 'Tick :'" : "'" + wanted + " :'";
    }

    /** The complete record, at the header's time in seconds. */
    LogRecord build() {
        return build(time, Clock.SECONDS);
    }

    /**
     * The complete record at the given time. The older shape is normalised to the current one: a command or tick
     * keeps the whole value as {@code arguments} and has {@code reply = ""}; a reply of two or more tokens has the
     * last token as {@code reply} and the others, joined by one space, as {@code arguments}; a reply of one token
     * has it as {@code reply} and {@code arguments = ""}. The protocol of the older shape is {@code ""}.
     */
    LogRecord build(double at, Clock clock) {
        if (labels == CURRENT) {
            return new LogRecord(line, at, level, kind, values[0], values[1], values[2], values[3],
                    values[4], values[5], clock);
        }
        String arguments = values[3];
        String reply = "";
        if (kind == RecordKind.REPLY) {
            String[] tokens = arguments.isEmpty() ? new String[0] : arguments.split("\\s+");
            reply = tokens.length == 0 ? "" : tokens[tokens.length - 1];
            arguments = String.join(" ", Arrays.asList(tokens).subList(0, Math.max(0, tokens.length - 1)));
        }
        return new LogRecord(line, at, level, kind, values[0], values[1], "", values[2], arguments, reply, clock);
    }

    private static RecordKind olderKind(String label) {
        for (RecordKind candidate : new RecordKind[] {RecordKind.COMMAND, RecordKind.REPLY, RecordKind.TICK}) {
            if (candidate.name().equalsIgnoreCase(label)) {
                return candidate;
            }
        }
        return null;
    }
}
