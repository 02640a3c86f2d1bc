package dev.predmon.parse;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * yarplogger's column layout, copied or exported: an entry starts with {@code <time> <LEVEL> <text>}, columns
 * separated by tabs or spaces. {@code <time>} is relative ({@code 71.818968}) or epoch seconds; the export layout
 * {@code <yarprun time> <local time> <LEVEL>} (level in angle brackets) is accepted too, taking the local time. A
 * record is an entry whose text is a record header ({@code <Kind> intercepted:} or {@code Message received:});
 * any other entry (the INFO raw bottle the monitor prints before each record, other components' messages) is
 * skipped. Times are seconds.
 */
final class ColumnsLayout extends RecordLayout {

    private static final String NUMBER = "[-+]?(?:\\d+(?:\\.\\d*)?|\\.\\d+)(?:[eE][-+]?\\d+)?";
    static final String HEADER_TEXT =
            "(?:(Command|Reply|Tick|Unknown)[ \\t]+intercepted|Message[ \\t]+received)[ \\t]*:[ \\t]*";
    /** A line whose text column is a record header; the times are checked afterwards to report bad ones. */
    static final Pattern HEADER = Pattern.compile(
            "\\s*(\\S+)(?:[ \\t]+(\\S+))?[ \\t]+<?([A-Z]+)>?[ \\t]+" + HEADER_TEXT);
    /** A line that merely ends like a header, to catch headers without time or level. */
    private static final Pattern HEADER_SUFFIX = Pattern.compile("(?:^|\\s)" + HEADER_TEXT + "$");
    /** The first line of any log entry (record or not). */
    private static final Pattern ENTRY = Pattern.compile(
            "\\s*" + NUMBER + "(?:[ \\t]+" + NUMBER + ")?[ \\t]+<?(?:TRACE|DEBUG|INFO|WARNING|ERROR|FATAL)>?(?:[ \\t].*)?");
    static final Pattern TIME = Pattern.compile(NUMBER);
    /** Exact powers of ten: a double holds 10^k exactly up to k = 22. */
    private static final double[] POWERS_OF_TEN = new double[23];

    static {
        POWERS_OF_TEN[0] = 1;
        for (int k = 1; k < POWERS_OF_TEN.length; k++) {
            POWERS_OF_TEN[k] = POWERS_OF_TEN[k - 1] * 10;
        }
    }

    /** The header's tokens, reused from line to line: a header is read for every record. */
    private final int[] starts = new int[6];
    private final int[] ends = new int[6];
    /** The last headers' bytes after their time, with their level and kind ({@link #knownHeader}). */
    private final byte[][] tails = new byte[4][];
    private final String[] tailLevels = new String[4];
    private final RecordKind[] tailKinds = new RecordKind[4];
    private int nextTail;

    ColumnsLayout(Consumer<LogRecord> records, Consumer<ParseProblem> problems) {
        super(records, problems);
    }

    @Override
    LogRecord build(RecordDraft done) {
        return done.build();
    }

    @Override
    public void line(String text, long number) {
        lineNumber = number;
        if (draft != null) {
            if (offerFieldLine(text)) {
                return;
            }
            notAField(text);
        }
        if (text.indexOf("intercepted") < 0 && text.indexOf("received") < 0) {
            return; // cannot be a record header, well-formed or not: another entry or its continuation
        }
        Matcher header = HEADER.matcher(text);
        if (header.matches()) {
            startRecord(header);
            return;
        }
        Matcher suffix = HEADER_SUFFIX.matcher(text);
        if (suffix.find() && !ENTRY.matcher(text).matches()) {
            // Another component's entry may end like a header; a line that is no entry at all is a broken one.
            error(number, "malformed record header: expected '<time> <LEVEL> " + suffix.group().strip()
                    + "', got " + quote(text));
        }
        // Anything else is another entry or its continuation: not a record, skipped.
    }

    private void startRecord(Matcher header) {
        String first = header.group(1);
        String second = header.group(2);
        if (!TIME.matcher(first).matches() || (second != null && !TIME.matcher(second).matches())) {
            error(lineNumber, "record header with a non-numeric time "
                    + quote(second == null ? first : first + " " + second) + ": expected seconds such as 71.818968");
            return;
        }
        double time = Double.parseDouble(second == null ? first : second);
        draft = new RecordDraft(lineNumber, time, header.group(3), header.group(4));
    }

    /**
     * A well-formed ASCII field line of the record in progress is taken straight from the bytes; outside a record, a
     * plain ASCII line that cannot start one (no {@code intercepted}, {@code received} or {@code <}) is skipped
     * undecoded, and a header of the usual shape, {@code <time> [<time>] <LEVEL> <Kind> intercepted:}, starts a
     * record without the header regex. Anything else goes the general way.
     */
    @Override
    public boolean fastLine(byte[] b, int offset, int len, long number) {
        lineNumber = number;
        if (draft != null) {
            return fastField(b, offset, len);
        }
        int end = offset + len;
        if (!Bytes.asciiWithoutAngle(b, offset, end)) {
            return false;
        }
        return knownHeader(b, offset, end) || !mayBeHeader(b, offset, end) || fastHeader(b, offset, end);
    }

    /**
     * A header whose bytes after its time are those of a header read before ({@code \tDEBUG\tReply intercepted:}):
     * the same level and kind, checked then, so only the time is read. False, having done nothing, for anything else.
     */
    private boolean knownHeader(byte[] b, int offset, int end) {
        int i = offset;
        while (i < end && isRegexBlank((char) b[i])) {
            i++;
        }
        int timeStart = i;
        while (i < end && b[i] != ' ' && b[i] != '\t') {
            i++;
        }
        int rest = end - i;
        for (int k = 0; k < tails.length; k++) {
            byte[] tail = tails[k];
            if (tail != null && tail.length == rest && Arrays.equals(tail, 0, rest, b, i, end)
                    && plainNumber(b, timeStart, i)) {
                startDraft(lineNumber, decimal(b, timeStart, i), tailLevels[k], tailKinds[k]);
                return true;
            }
        }
        return false;
    }

    /** Remembers what follows the time of a header {@link #fastHeader} read: the next such header is known. */
    private void rememberTail(byte[] b, int tailStart, int end, String level, RecordKind kind) {
        int k = nextTail;
        nextTail = (nextTail + 1) % tails.length;
        tails[k] = Arrays.copyOfRange(b, tailStart, end);
        tailLevels[k] = level;
        tailKinds[k] = kind;
    }

    /** A header of the usual shape, tokens separated by blanks and tabs; false for anything else. */
    private boolean fastHeader(byte[] b, int offset, int end) {
        int n = 0;
        int i = offset;
        while (i < end && isRegexBlank((char) b[i])) {
            i++;
        }
        while (i < end) {
            if (n == starts.length) {
                return false;
            }
            starts[n] = i;
            while (i < end && b[i] != ' ' && b[i] != '\t') {
                i++;
            }
            ends[n++] = i;
            while (i < end && (b[i] == ' ' || b[i] == '\t')) {
                i++;
            }
        }
        if ((n != 4 && n != 5) || !tokenIs(b, starts[n - 1], ends[n - 1], "intercepted:")) {
            return false;
        }
        RecordKind kind = kindOf(b, starts[n - 2], ends[n - 2]);
        int levelAt = n - 3;
        if (kind == null || !upperLetters(b, starts[levelAt], ends[levelAt])
                || !plainNumber(b, starts[0], ends[0]) || (n == 5 && !plainNumber(b, starts[1], ends[1]))) {
            return false;
        }
        int t = n == 5 ? 1 : 0;
        double time = decimal(b, starts[t], ends[t]);
        String level = strings().of(b, starts[levelAt], ends[levelAt] - starts[levelAt]);
        startDraft(lineNumber, time, level, kind);
        if (n == 4) {
            rememberTail(b, ends[0], end, level, kind);
        }
        return true;
    }

    private static boolean tokenIs(byte[] b, int start, int end, String word) {
        return end - start == word.length() && startsWith(b, start, end, word);
    }

    private static RecordKind kindOf(byte[] b, int start, int end) {
        if (tokenIs(b, start, end, "Command")) {
            return RecordKind.COMMAND;
        }
        if (tokenIs(b, start, end, "Reply")) {
            return RecordKind.REPLY;
        }
        if (tokenIs(b, start, end, "Tick")) {
            return RecordKind.TICK;
        }
        return tokenIs(b, start, end, "Unknown") ? RecordKind.UNKNOWN : null;
    }

    private static boolean upperLetters(byte[] b, int start, int end) {
        for (int i = start; i < end; i++) {
            if (b[i] < 'A' || b[i] > 'Z') {
                return false;
            }
        }
        return end > start;
    }

    /**
     * The value of a {@link #plainNumber}, exactly as {@link Double#parseDouble} gives it. With at most 2^53 as the
     * digits' integer and at most 22 decimals, both the integer and the power of ten are exact doubles, so their
     * quotient is the correctly rounded value (Clinger's fast path); anything longer is left to the JDK. Parsing
     * each header's time through a string was the largest single cost of the fast path.
     */
    static double decimal(byte[] b, int start, int end) {
        boolean negative = b[start] == '-';
        long digits = 0;
        int decimals = -1;
        int count = 0;
        for (int i = negative ? start + 1 : start; i < end; i++) {
            if (b[i] == '.') {
                decimals = 0;
            } else {
                if (++count > 18) {
                    return Double.parseDouble(new String(b, start, end - start, StandardCharsets.ISO_8859_1));
                }
                digits = digits * 10 + (b[i] - '0');
                if (decimals >= 0) {
                    decimals++;
                }
            }
        }
        if (digits > (1L << 53) || decimals >= POWERS_OF_TEN.length) {
            return Double.parseDouble(new String(b, start, end - start, StandardCharsets.ISO_8859_1));
        }
        double value = decimals > 0 ? digits / POWERS_OF_TEN[decimals] : (double) digits;
        return negative ? -value : value;
    }

    /** Digits with at most one '.', an optional leading '-': what a log's time column holds. */
    private static boolean plainNumber(byte[] b, int start, int end) {
        int i = start < end && b[start] == '-' ? start + 1 : start;
        boolean digit = false;
        boolean dot = false;
        for (; i < end; i++) {
            if (b[i] >= '0' && b[i] <= '9') {
                digit = true;
            } else if (b[i] == '.' && !dot) {
                dot = true;
            } else {
                return false;
            }
        }
        return digit;
    }
}
