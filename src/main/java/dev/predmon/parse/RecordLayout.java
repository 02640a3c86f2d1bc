package dev.predmon.parse;

import java.util.Arrays;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * What every layout shares: the record in progress ({@link RecordDraft}), field lines ({@code <Label> : <value>},
 * any spacing, value trimmed), the fast path for well-formed ASCII field lines, and how broken records are
 * reported. A layout adds how its header lines look and where a record's time comes from
 * ({@link #build(RecordDraft)}).
 */
abstract class RecordLayout implements LogLayout {

    /** Longest quotation of an input line in a problem message. */
    private static final int QUOTE_LIMIT = 80;

    private final Consumer<LogRecord> records;
    private final Consumer<ParseProblem> problems;
    RecordDraft draft;
    /** The draft of the last record built, which {@link #startDraft} reuses; {@code null} if none. */
    private RecordDraft spare;
    /**
     * Per field of the current shape, the bytes of its last line up to and including the colon: logs indent and pad
     * labels the same way on every record, so one compare replaces scanning blanks, label and colon.
     */
    private final byte[][] prefixes = new byte[6][];
    /** The number of the line being read. */
    long lineNumber;
    /** The thread that read the last field line, and its table of strings: one thread-local look-up per thread. */
    private Thread reader;
    private AsciiStrings strings;

    RecordLayout(Consumer<LogRecord> records, Consumer<ParseProblem> problems) {
        this.records = Objects.requireNonNull(records, "records");
        this.problems = Objects.requireNonNull(problems, "problems");
    }

    /** The complete record of {@code done}, with its time. */
    abstract LogRecord build(RecordDraft done);

    @Override
    public void overlongLine(long number, long bytes) {
        lineNumber = number;
        String lost = draft == null ? "" : "; dropped the record started at line " + draft.line;
        draft = null;
        error(number, "line of " + bytes + " bytes is longer than the limit and was skipped" + lost);
    }

    @Override
    public void endOfInput() {
        if (draft != null) {
            problems.accept(new ParseProblem(draft.line, ParseProblem.Severity.WARNING,
                    "log ends in the middle of a record started at line " + draft.line + ": missing "
                            + draft.expected()));
            draft = null;
        }
    }

    /**
     * Offers {@code text} as a field line of the record in progress if it is one ({@code FIELD}: blanks, a label of
     * letters, blanks or tabs, a colon, the value); returns whether it was one (a field line with an unexpected
     * label is reported and breaks the record). Hand-written because six of every seven lines of a log are
     * field lines and a regex was the parser's main cost.
     */
    final boolean offerFieldLine(String text) {
        int n = text.length();
        int i = 0;
        while (i < n && isRegexBlank(text.charAt(i))) {
            i++;
        }
        int labelStart = i;
        while (i < n && isAsciiLetter(text.charAt(i))) {
            i++;
        }
        int labelEnd = i;
        while (i < n && (text.charAt(i) == ' ' || text.charAt(i) == '\t')) {
            i++;
        }
        if (labelEnd == labelStart || i == n || text.charAt(i) != ':') {
            return false;
        }
        offerField(text.substring(labelStart, labelEnd), text.substring(i + 1));
        return true;
    }

    /** Whether {@code text} cannot continue the record in progress: it is not a field line. */
    final boolean cutBy(String text) {
        if (draft == null) {
            return false;
        }
        String t = text.strip();
        int colon = t.indexOf(':');
        return colon < 1 || !t.substring(0, colon).strip().chars().allMatch(c -> isAsciiLetter((char) c));
    }

    /** The record in progress is broken by {@code text}, which is not its next field line. */
    final void notAField(String text) {
        brokenRecord("expected " + draft.expected() + " line of the record started at line " + draft.line
                + ", got " + quote(text));
    }

    final void offerField(String label, String value) {
        if (!draft.offer(label, value.trim())) {
            brokenRecord("expected " + draft.expected() + " line of the record started at line " + draft.line
                    + ", got " + quote(label + " :" + value));
        } else if (draft.complete()) {
            RecordDraft done = draft;
            draft = null;
            records.accept(build(done));
            spare = done;
        }
    }

    /** Starts a record of the current shape, reusing the last record's draft: one fewer allocation per record. */
    final void startDraft(long line, double time, String level, RecordKind kind) {
        RecordDraft reused = spare;
        spare = null;
        draft = reused == null ? new RecordDraft(line, time, level, kind) : reused.restart(line, time, level, kind);
    }

    /**
     * The fast path for a field line of the record in progress: a well-formed ASCII field line with the label
     * expected next is taken straight from the bytes (decoding each into a string, cutting label and value out of
     * it and trimming the value was most of the parser's time). False, having done nothing, for anything else.
     */
    final boolean fastField(byte[] b, int offset, int len) {
        int end = offset + len;
        int field = draft.currentField();
        byte[] known = field >= 0 ? prefixes[field] : null;
        int valueStart;
        if (known != null && len >= known.length && Arrays.equals(known, 0, known.length, b, offset, offset + known.length)) {
            // The same bytes up to the colon as this field's last line: the same label, checked then.
            valueStart = offset + known.length;
        } else {
            int i = offset;
            while (i < end && isRegexBlank((char) b[i])) {
                i++;
            }
            int labelStart = i;
            while (i < end && isAsciiLetter((char) b[i])) {
                i++;
            }
            int labelEnd = i;
            while (i < end && (b[i] == ' ' || b[i] == '\t')) {
                i++;
            }
            if (labelEnd == labelStart || i == end || b[i] != ':' || !draft.expects(b, labelStart, labelEnd - labelStart)) {
                return false;
            }
            valueStart = i + 1;
            if (field >= 0) {
                prefixes[field] = Arrays.copyOfRange(b, offset, valueStart);
            }
        }
        int valueEnd = end;
        while (valueStart < valueEnd && (b[valueStart] & 0xff) <= ' ') {
            if (b[valueStart] == 0x1b) {
                return false;
            }
            valueStart++;
        }
        while (valueEnd > valueStart && (b[valueEnd - 1] & 0xff) <= ' ') {
            if (b[valueEnd - 1] == 0x1b) {
                return false;
            }
            valueEnd--;
        }
        // Non-ASCII, a save-file marker or a colour code: the general path decides (null).
        String value = strings().ofPlain(b, valueStart, valueEnd - valueStart);
        if (value == null) {
            return false;
        }
        draft.take(value);
        if (draft.complete()) {
            RecordDraft done = draft;
            draft = null;
            records.accept(build(done));
            spare = done;
        }
        return true;
    }

    /**
     * This thread's {@link AsciiStrings}, looked up again only when another thread reads this log: a table is never
     * shared between threads, and a thread-local look-up per field line was a visible share of the parser's time.
     */
    final AsciiStrings strings() {
        Thread t = Thread.currentThread();
        if (t != reader) {
            reader = t;
            strings = AsciiStrings.local();
        }
        return strings;
    }

    final void brokenRecord(String message) {
        draft = null;
        error(lineNumber, message);
    }

    final void error(long line, String message) {
        problems.accept(new ParseProblem(line, ParseProblem.Severity.ERROR, message));
    }

    /** Exactly the characters of the regex class {@code \\s}. */
    static boolean isRegexBlank(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\u000B' || c == '\f' || c == '\r';
    }

    static boolean isAsciiLetter(char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    }

    static boolean startsWith(byte[] b, int at, int end, String word) {
        if (end - at < word.length()) {
            return false;
        }
        for (int i = 0; i < word.length(); i++) {
            if (b[at + i] != word.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    /** Whether the bytes contain {@code intercepted} or {@code received}: only such a line can start a record. */
    static boolean mayBeHeader(byte[] b, int offset, int end) {
        for (int k = offset; k < end; k++) {
            byte c = b[k];
            if ((c == 'i' || c == 'r') && (startsWith(b, k, end, "intercepted") || startsWith(b, k, end, "received"))) {
                return true;
            }
        }
        return false;
    }

    static String quote(String text) {
        String trimmed = text.strip();
        return "'" + (trimmed.length() > QUOTE_LIMIT ? trimmed.substring(0, QUOTE_LIMIT) + "..." : trimmed) + "'";
    }
}
