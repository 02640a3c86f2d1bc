package dev.predmon.parse;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Push parser for YARP monitor logs: fed one physical line at a time, it emits each complete record once.
 * Constant memory: it holds at most one record in progress.
 *
 * <h2>Text logs (yarplogger's columns, copied or exported)</h2>
 * An entry starts with {@code <time> <LEVEL> <text>}, columns separated by tabs or spaces. {@code <time>} is
 * relative ({@code 71.818968}) or epoch seconds; the export layout {@code <yarprun time> <local time> <LEVEL>}
 * (yarplogger's "export to text", level in angle brackets) is accepted too, taking the local time. A record is
 * an entry whose text is a record header; any other entry (the INFO raw bottle the monitor prints before each
 * record, other components' messages) is skipped. Two record layouts:
 * <ul>
 *   <li>current: {@code <Kind> intercepted:} ({@code Command}, {@code Reply}, {@code Tick}, {@code Unknown})
 *       then {@code From}, {@code To}, {@code Protocol}, {@code Command}, {@code Arguments}, {@code Reply}
 *       lines; complete at the {@code Reply} line.</li>
 *   <li>older: {@code Message received:} then {@code From}, {@code To}, one of {@code Command}/{@code Reply}/
 *       {@code Tick} (the label is the kind, the value the method name), {@code Arguments} (all arguments and
 *       reply values, space separated); complete at the {@code Arguments} line. The protocol is {@code ""}.
 *       Its values are normalised to the current layout's shape: a command or tick keeps the whole value as
 *       {@code arguments} and has {@code reply = ""}; a reply of two or more tokens has the last token as
 *       {@code reply} and the others, joined by one space, as {@code arguments}; a reply of one token has it as
 *       {@code reply} and {@code arguments = ""}.</li>
 * </ul>
 * Field labels may have any spacing around them and the colon; values are trimmed and may be empty.
 *
 * <h2>yarplogger save files</h2>
 * Detected by a first line {@code 1} (the format version) or by the first {@code <#STRING_START#>} marker.
 * Layout as written by {@code LoggerEngine::save_all_logs_to_file} (robotology/yarp,
 * {@code src/libYARP_logger/src/yarp/logger/YarpLoggerFiles.cpp}), one value a line, empty strings written
 * {@code NULL-DATA}: version, number of ports, then per port its ip address, complete port name, prefix,
 * system, process name, pid, six level counters, log size and entry count, then per entry the yarprun time
 * stamp, the local time stamp, the level as a number (0 undefined, 1 TRACE ... 6 FATAL) and
 * {@code <#STRING_START#>text<#STRING_END#>}, the text spanning lines when it has newlines (a monitor record's
 * seven lines). Like yarplogger's own loader, which searches for the next start marker, the parser does not
 * count the per-port headers: the three lines before a start marker are the entry's time stamps and level.
 * The record's time is the local time stamp, or the yarprun one when the local one is {@code NULL-DATA}.
 *
 * <h2>Broken input</h2>
 * A header that cannot be read, a missing, repeated, misplaced or unknown field, or an entry that ends before
 * its record does is reported as an {@link ParseProblem.Severity#ERROR} at its line; the record is dropped and
 * parsing resumes at the next header. Nothing the input holds makes the parser throw.
 */
public final class LogParser {

    private static final String NUMBER = "[-+]?(?:\\d+(?:\\.\\d*)?|\\.\\d+)(?:[eE][-+]?\\d+)?";
    private static final String HEADER_TEXT =
            "(?:(Command|Reply|Tick|Unknown)[ \\t]+intercepted|Message[ \\t]+received)[ \\t]*:[ \\t]*";
    /** A line whose text column is a record header; the times are checked afterwards to report bad ones. */
    private static final Pattern HEADER = Pattern.compile(
            "\\s*(\\S+)(?:[ \\t]+(\\S+))?[ \\t]+<?([A-Z]+)>?[ \\t]+" + HEADER_TEXT);
    /** A line that merely ends like a header, to catch headers without time or level. */
    private static final Pattern HEADER_SUFFIX = Pattern.compile("(?:^|\\s)" + HEADER_TEXT + "$");
    /** The first line of any log entry of a text log (record or not). */
    private static final Pattern ENTRY = Pattern.compile(
            "\\s*" + NUMBER + "(?:[ \\t]+" + NUMBER + ")?[ \\t]+<?(?:TRACE|DEBUG|INFO|WARNING|ERROR|FATAL)>?(?:[ \\t].*)?");
    private static final Pattern TEXT_HEADER = Pattern.compile("\\s*" + HEADER_TEXT);
    private static final Pattern FIELD = Pattern.compile("\\s*([A-Za-z]+)[ \\t]*:(.*)");
    private static final Pattern TIME = Pattern.compile(NUMBER);
    private static final Pattern SAVE_LEVEL = Pattern.compile("\\d{1,9}");

    private static final String START_MARK = "<#STRING_START#>";
    private static final String END_MARK = "<#STRING_END#>";
    private static final String NULL_DATA = "NULL-DATA";
    /** yarplogger's {@code LogLevelEnum} in order. */
    private static final String[] SAVE_LEVELS = {"UNDEFINED", "TRACE", "DEBUG", "INFO", "WARNING", "ERROR", "FATAL"};
    /** Longest quotation of an input line in a problem message. */
    private static final int QUOTE_LIMIT = 80;

    private enum Mode { UNKNOWN, TEXT, SAVE }

    private final Consumer<LogRecord> records;
    private final Consumer<ParseProblem> problems;

    private long lineNumber;
    private Mode mode = Mode.UNKNOWN;
    /** The line that made the parser read the input as a save file, for messages. */
    private long saveSince;
    private Draft draft;

    // Save-file state: the last three value lines seen outside a text block, and the block being read.
    private final RecentLines lastValues = new RecentLines();
    private final AsciiStrings strings = new AsciiStrings();
    private boolean inBlock;
    private boolean blockFirstLine;
    private long blockLine;
    private double blockTime;
    private String blockLevel;
    private boolean blockBroken;

    /**
     * @param records  receives every complete record
     * @param problems receives broken or truncated records
     */
    public LogParser(Consumer<LogRecord> records, Consumer<ParseProblem> problems) {
        this.records = Objects.requireNonNull(records, "records");
        this.problems = Objects.requireNonNull(problems, "problems");
    }

    /** Feeds one line without its terminator (a trailing {@code '\r'} is tolerated). */
    public void acceptLine(String line) {
        lineNumber++;
        String text = line.endsWith("\r") ? line.substring(0, line.length() - 1) : line;
        if (lineNumber == 1 && text.startsWith("\uFEFF")) {
            text = text.substring(1);
        }
        if (mode == Mode.UNKNOWN) {
            mode = text.trim().equals("1") ? Mode.SAVE : Mode.TEXT;
            saveSince = lineNumber;
        }
        if (mode == Mode.TEXT && text.contains(START_MARK)) {
            // A save file whose version line was lost: the values before the marker were remembered anyway.
            mode = Mode.SAVE;
            saveSince = lineNumber;
        }
        if (mode == Mode.SAVE) {
            acceptSaveLine(text);
        } else {
            rememberValue(text);
            acceptTextLine(text);
        }
    }

    /**
     * A line longer than the reader's cap was skipped: it counts as a line, is reported as an error, and breaks
     * the record in progress if there is one.
     *
     * @param bytes the skipped line's length in bytes
     */
    public void acceptOverlongLine(long bytes) {
        lineNumber++;
        if (mode == Mode.UNKNOWN) {
            mode = Mode.TEXT;
        }
        String lost = draft == null ? "" : "; dropped the record started at line " + draft.line;
        draft = null;
        // The skipped line cannot be a save-file entry's header line any more.
        blockFirstLine = false;
        rememberValue("");
        problems.accept(new ParseProblem(lineNumber, ParseProblem.Severity.ERROR,
                "line of " + bytes + " bytes is longer than the limit and was skipped" + lost));
    }

    /** The input is over (batch mode): a record still in progress is reported once as a WARNING. */
    public void endOfInput() {
        if (draft != null) {
            problems.accept(new ParseProblem(draft.line, ParseProblem.Severity.WARNING,
                    "log ends in the middle of a record started at line " + draft.line + ": missing "
                            + draft.expected()));
            draft = null;
        }
        inBlock = false;
    }

    /** Forgets the record in progress and restarts line numbering (the file was truncated or replaced). */
    public void reset() {
        lineNumber = 0;
        mode = Mode.UNKNOWN;
        draft = null;
        inBlock = false;
        lastValues.clear();
    }

    /** The number of lines seen since construction or the last {@link #reset()}. */
    public long lineNumber() {
        return lineNumber;
    }

    /**
     * This parser as a {@link LineSink}: lines are {@link #acceptLine accepted}, overlong lines reported, and a
     * restart first reports a record left in progress (as {@link #endOfInput()} does) then {@link #reset()}s.
     */
    public LineSink lineSink() {
        return new LineSink() {
            @Override
            public void line(String line) {
                acceptLine(line);
            }

            @Override
            public void line(byte[] bytes, int offset, int length) {
                acceptLine(bytes, offset, length);
            }

            @Override
            public void restarted(String reason) {
                endOfInput();
                reset();
            }

            @Override
            public void overlongLine(long bytes) {
                acceptOverlongLine(bytes);
            }
        };
    }

    // ---- text logs ---------------------------------------------------------------------------------------

    private void acceptTextLine(String text) {
        if (draft != null) {
            if (offerFieldLine(text)) {
                return;
            }
            brokenRecord("expected " + draft.expected() + " line of the record started at line " + draft.line
                    + ", got " + quote(text));
        }
        if (text.indexOf("intercepted") < 0 && text.indexOf("received") < 0) {
            return; // cannot be a record header, well-formed or not: another entry or its continuation
        }
        Matcher header = HEADER.matcher(text);
        if (header.matches()) {
            startTextRecord(header);
            return;
        }
        Matcher suffix = HEADER_SUFFIX.matcher(text);
        if (suffix.find() && !ENTRY.matcher(text).matches()) {
            // Another component's entry may end like a header; a line that is no entry at all is a broken one.
            error(lineNumber, "malformed record header: expected '<time> <LEVEL> " + suffix.group().strip()
                    + "', got " + quote(text));
        }
        // Anything else is another entry or its continuation: not a record, skipped.
    }

    private void startTextRecord(Matcher header) {
        String first = header.group(1);
        String second = header.group(2);
        if (!TIME.matcher(first).matches() || (second != null && !TIME.matcher(second).matches())) {
            error(lineNumber, "record header with a non-numeric time "
                    + quote(second == null ? first : first + " " + second) + ": expected seconds such as 71.818968");
            return;
        }
        double time = Double.parseDouble(second == null ? first : second);
        draft = new Draft(lineNumber, time, header.group(3), header.group(4));
    }

    // ---- save files --------------------------------------------------------------------------------------

    private void acceptSaveLine(String text) {
        if (HEADER.matcher(text).matches()) {
            // A text log's record in a file read as a save file (first line "1", or a stray start marker
            // earlier): its fields are not save-file values, so without this it would vanish silently.
            error(lineNumber, "record header of a text log inside a yarplogger save file (read as one because of "
                    + "line " + saveSince + "); record skipped");
        }
        int start = text.indexOf(START_MARK);
        int end = text.indexOf(END_MARK);
        if (inBlock && start >= 0 && (end < 0 || start < end)) {
            // The previous entry never got its end marker: it is cut off here.
            if (draft != null) {
                brokenRecord("expected " + draft.expected() + " line of the record started at line " + draft.line
                        + ", got the start of the next entry");
            }
            inBlock = false;
        }
        if (inBlock) {
            rememberValue(text);
            blockText(text);
        } else if (start >= 0) {
            beginBlock();
            blockText(text.substring(start + START_MARK.length()));
        } else {
            rememberValue(text);
        }
    }

    private void beginBlock() {
        inBlock = true;
        blockFirstLine = true;
        blockLine = lineNumber;
        blockBroken = false;
        String yarprunTime = lastValues.trimmed(0);
        String localTime = lastValues.trimmed(1);
        String level = lastValues.trimmed(2);
        lastValues.clear();
        if (level == null || !SAVE_LEVEL.matcher(level).matches()) {
            blockBroken = true;
            error(lineNumber, "expected the entry's level (a number from 0 to 6) on the line before "
                    + START_MARK + ", got " + quote(level == null ? "" : level));
            return;
        }
        int levelNumber = Integer.parseInt(level);
        blockLevel = levelNumber < SAVE_LEVELS.length ? SAVE_LEVELS[levelNumber] : SAVE_LEVELS[0];
        String time = localTime != null && TIME.matcher(localTime).matches() ? localTime : yarprunTime;
        if (time == null || !TIME.matcher(time).matches()) {
            blockBroken = true;
            error(lineNumber, "expected the entry's yarprun and local time stamps (seconds or " + NULL_DATA
                    + ") on the lines before its level, got " + quote(yarprunTime == null ? "" : yarprunTime)
                    + " and " + quote(localTime == null ? "" : localTime));
            return;
        }
        blockTime = Double.parseDouble(time);
    }

    private void blockText(String text) {
        int end = text.indexOf(END_MARK);
        String content = end < 0 ? text : text.substring(0, end);
        // Text ending in a newline puts the end marker alone on the next line: that line holds nothing.
        if (end < 0 || blockFirstLine || !content.isBlank()) {
            blockTextLine(content);
        }
        if (end >= 0) {
            if (draft != null) {
                brokenRecord("entry text ended before the record started at line " + draft.line
                        + " was complete: expected " + draft.expected());
            }
            inBlock = false;
        }
    }

    private void blockTextLine(String content) {
        if (blockFirstLine) {
            blockFirstLine = false;
            Matcher header = TEXT_HEADER.matcher(content);
            if (!blockBroken && header.matches()) {
                draft = new Draft(blockLine, blockTime, blockLevel, header.group(1));
            }
            return;
        }
        if (draft == null) {
            return;
        }
        Matcher field = FIELD.matcher(content);
        if (field.matches()) {
            offerField(field.group(1), field.group(2));
        } else {
            brokenRecord("expected " + draft.expected() + " line of the record started at line " + draft.line
                    + ", got " + quote(content));
        }
    }

    // ---- shared ------------------------------------------------------------------------------------------

    /**
     * Offers {@code text} as a field line ({@code FIELD}: blanks, a label of letters, blanks or tabs, a colon, the
     * value) if it is one. Hand-written because six of every seven lines of a log are field lines and the regex
     * was the parser's main cost.
     */
    private boolean offerFieldLine(String text) {
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

    private static String trimmed(String s) {
        return s == null ? null : s.trim();
    }

    /** Exactly the characters of the regex class {@code \\s}. */
    private static boolean isRegexBlank(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\u000B' || c == '\f' || c == '\r';
    }

    private static boolean isAsciiLetter(char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    }

    private void offerField(String label, String value) {
        if (!draft.offer(label, value.trim())) {
            brokenRecord("expected " + draft.expected() + " line of the record started at line " + draft.line
                    + ", got " + quote(label + " :" + value));
        } else if (draft.complete()) {
            LogRecord record = draft.build();
            draft = null;
            records.accept(record);
        }
    }

    private void brokenRecord(String message) {
        draft = null;
        error(lineNumber, message);
    }

    private void error(long line, String message) {
        problems.accept(new ParseProblem(line, ParseProblem.Severity.ERROR, message));
    }

    private void rememberValue(String text) {
        lastValues.push(text); // trimmed only when used: this runs on every line of a text log
    }

    /**
     * A line as bytes: a well-formed ASCII field line of the text record in progress is taken straight from the
     * bytes (six of every seven lines of a log; decoding each into a string, cutting label and value out of it
     * and trimming the value was most of the parser's time); any other line takes the general path,
     * {@link #acceptLine}, exactly as before.
     */
    void acceptLine(byte[] b, int offset, int len) {
        boolean done = mode == Mode.TEXT && (draft != null ? fastField(b, offset, len) : fastOutside(b, offset, len));
        if (!done) {
            acceptLine(new String(b, offset, len, StandardCharsets.UTF_8));
        }
    }

    /**
     * The fast path for a line outside a record: a plain ASCII line that cannot start a record (no
     * {@code intercepted}, {@code received} or {@code <}) is only remembered; a header of the usual shape,
     * {@code <time> [<time>] <LEVEL> <Kind> intercepted:}, starts a record without the header regex. Anything else
     * goes the general way.
     */
    private boolean fastOutside(byte[] b, int offset, int len) {
        int end = offset + len;
        boolean interesting = false;
        for (int k = offset; k < end; k++) {
            byte c = b[k];
            if (c < 0 || c == '<') {
                return false;
            }
            if ((c == 'i' || c == 'r') && (startsWith(b, k, end, "intercepted") || startsWith(b, k, end, "received"))) {
                interesting = true;
            }
        }
        if (!interesting) {
            lineNumber++;
            lastValues.push(b, offset, len);
            return true;
        }
        return fastHeader(b, offset, end);
    }

    /** A header of the usual shape, tokens separated by blanks and tabs; false for anything else. */
    private boolean fastHeader(byte[] b, int offset, int end) {
        int[] starts = new int[6];
        int[] ends = new int[6];
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
        double time = Double.parseDouble(new String(b, starts[t], ends[t] - starts[t], StandardCharsets.ISO_8859_1));
        lineNumber++;
        lastValues.push(b, offset, end - offset);
        draft = new Draft(lineNumber, time, strings.of(b, starts[levelAt], ends[levelAt] - starts[levelAt]), kind);
        return true;
    }

    private static boolean startsWith(byte[] b, int at, int end, String word) {
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

    /** The fast path of {@link #acceptLine(byte[], int, int)}; false (nothing done) sends the line the slow way. */
    private boolean fastField(byte[] b, int offset, int len) {
        int end = offset + len;
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
        if (labelEnd == labelStart || i == end || b[i] != ':') {
            return false;
        }
        int valueStart = i + 1;
        for (int k = valueStart; k < end; k++) {
            if (b[k] < 0 || b[k] == '<') {
                return false; // non-ASCII, or perhaps a save-file marker: the general path decides
            }
        }
        int valueEnd = end;
        while (valueStart < valueEnd && (b[valueStart] & 0xff) <= ' ') {
            valueStart++;
        }
        while (valueEnd > valueStart && (b[valueEnd - 1] & 0xff) <= ' ') {
            valueEnd--;
        }
        if (!draft.expects(b, labelStart, labelEnd - labelStart)) {
            return false;
        }
        lineNumber++;
        lastValues.push(b, offset, len);
        draft.offer(draft.expectedLabel(), strings.of(b, valueStart, valueEnd - valueStart));
        if (draft.complete()) {
            LogRecord record = draft.build();
            draft = null;
            records.accept(record);
        }
        return true;
    }

    private static String quote(String text) {
        String trimmed = text.strip();
        return "'" + (trimmed.length() > QUOTE_LIMIT ? trimmed.substring(0, QUOTE_LIMIT) + "..." : trimmed) + "'";
    }

    /** The record in progress: its header, the fields read so far, and which label comes next. */
    private static final class Draft {
        private static final String[] CURRENT = {"From", "To", "Protocol", "Command", "Arguments", "Reply"};
        /** {@code null} stands for the kind label of the older layout: Command, Reply or Tick. */
        private static final String[] OLDER = {"From", "To", null, "Arguments"};

        final long line;
        private final double time;
        private final String level;
        private final String[] labels;
        private final String[] values;
        private RecordKind kind;
        private int next;

        /** @param kindWord the {@code <Kind>} of a current header, {@code null} for {@code Message received:} */
        Draft(long line, double time, String level, String kindWord) {
            this(line, time, level, kindWord == null ? null : RecordKind.valueOf(kindWord.toUpperCase(Locale.ROOT)));
        }

        /** @param kind the kind of a current header, {@code null} for {@code Message received:} */
        Draft(long line, double time, String level, RecordKind kind) {
            this.line = line;
            this.time = time;
            this.level = level;
            this.labels = kind == null ? OLDER : CURRENT;
            this.values = new String[labels.length];
            this.kind = kind;
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

        /** The label expected next, as {@link #offer} compares it. */
        String expectedLabel() {
            return labels[next];
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

        LogRecord build() {
            if (labels == CURRENT) {
                return new LogRecord(line, time, level, kind, values[0], values[1], values[2], values[3],
                        values[4], values[5]);
            }
            String arguments = values[3];
            String reply = "";
            if (kind == RecordKind.REPLY) {
                String[] tokens = arguments.isEmpty() ? new String[0] : arguments.split("\\s+");
                reply = tokens.length == 0 ? "" : tokens[tokens.length - 1];
                arguments = String.join(" ", Arrays.asList(tokens).subList(0, Math.max(0, tokens.length - 1)));
            }
            return new LogRecord(line, time, level, kind, values[0], values[1], "", values[2], arguments, reply);
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
}
