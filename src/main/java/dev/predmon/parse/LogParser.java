package dev.predmon.parse;

import java.nio.charset.StandardCharsets;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * Push parser for YARP monitor logs: fed one physical line at a time, it emits each complete record once.
 * Constant memory: it holds at most one record in progress.
 *
 * <p>The layout is detected once per file, and every line then goes to that layout's grammar
 * ({@link LogLayout}):
 * <ul>
 *   <li>{@link ConsoleLayout}: the monitor's console output redirected to a file, with colour codes,
 *       {@code [DEBUG] Command intercepted:} headers and no time stamps (the clock is the tree's tick);</li>
 *   <li>{@link ColumnsLayout}: yarplogger's columns, {@code <time> <LEVEL> <text>}, copied or exported;</li>
 *   <li>{@link SaveFileLayout}: yarplogger's own save file.</li>
 * </ul>
 * A first line {@code 1} (the save file's version) or a {@code <#STRING_START#>} marker means a save file; else
 * the first line that ends like a record header decides: a console header ({@code [LEVEL] <Kind> intercepted:},
 * colour codes allowed) means a console capture, anything else the column layout (which reports a header without
 * time and level as malformed). Lines before the decision are other programs' lines: they hold no record.
 *
 * <p>Both record shapes (current {@code <Kind> intercepted:} and older {@code Message received:}) are read in every
 * layout; see {@link RecordDraft}. Field labels may have any spacing around them and the colon; values are trimmed
 * and may be empty.
 *
 * <h2>Broken input</h2>
 * A header that cannot be read, a missing, repeated, misplaced or unknown field, or an entry that ends before
 * its record does is reported as an {@link ParseProblem.Severity#ERROR} at its line; the record is dropped and
 * parsing resumes at the next header. Nothing the input holds makes the parser throw.
 */
public final class LogParser {

    /** How a record header ends, in every layout: what a header cut before its end lacks part of. */
    private static final String[] HEADER_PHRASES = {"Command intercepted:", "Reply intercepted:", "Tick intercepted:",
        "Unknown intercepted:", "Message received:"};

    private final Consumer<LogRecord> records;
    private final Consumer<ParseProblem> problems;

    private long lineNumber;
    /** {@code null} until the layout is known. */
    private LogLayout layout;
    /** While the layout is unknown: the last three lines, which a save file's first entry needs. */
    private final RecentLines recent = new RecentLines();
    /** YARP's own lines about the monitor's port before the layout was known ({@link YarpLines}). */
    private long yarpLines;

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
        if (layout == null && !detect(text)) {
            recent.push(text);
            if (YarpLines.is(text)) {
                yarpLines++;
            }
            return;
        }
        layout.line(text, lineNumber);
    }

    /**
     * A line as bytes: once the layout is known, its grammar may take the line straight from the bytes (most lines
     * of a log); any other line takes the general path, {@link #acceptLine(String)}.
     */
    void acceptLine(byte[] b, int offset, int len) {
        if (layout != null && layout.fastLine(b, offset, len, lineNumber + 1)) {
            lineNumber++;
            return;
        }
        acceptLine(new String(b, offset, len, StandardCharsets.UTF_8));
    }

    /**
     * The input's last line, which no terminator ended: the capture may have stopped in the middle of it. It is read
     * as any line, except that one that cannot continue the record in progress is taken as the cut rather than as
     * a broken record: {@link #endOfInput()} then reports the record once, as cut off.
     */
    public void acceptLastLine(String line) {
        if (layout instanceof RecordLayout grammar && grammar.cutBy(line)) {
            lineNumber++;
            return;
        }
        if (cutHeader(line)) {
            // Cut inside the header, the record is as lost as one cut inside a field line, and says so the same way.
            lineNumber++;
            problems.accept(new ParseProblem(lineNumber, ParseProblem.Severity.WARNING, "log ends in the middle of a "
                    + "record started at line " + lineNumber + ": missing the rest of its header and its fields"));
            return;
        }
        acceptLine(line);
    }

    /**
     * Whether {@code text} is the beginning of a record header of either layout, cut before its end
     * ({@code 95.0\tDEBUG\tReply inter}, {@code [DEBUG] Command}): completed with the rest of one of the header
     * phrases, it is a header. A complete header is not a cut one.
     */
    static boolean cutHeader(String text) {
        String plain = ConsoleLayout.withoutColours(text);
        if (ConsoleLayout.HEADER.matcher(plain).matches() || ColumnsLayout.HEADER.matcher(plain).matches()) {
            return false;
        }
        for (String phrase : HEADER_PHRASES) {
            // from k = 1: the phrase itself must have begun, or any line ending in a blank would count
            for (int k = 1; k < phrase.length(); k++) {
                if (plain.endsWith(phrase.substring(0, k))) {
                    String completed = plain + phrase.substring(k);
                    if (ConsoleLayout.HEADER.matcher(completed).matches()
                            || ColumnsLayout.HEADER.matcher(completed).matches()) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /** Decides the layout if {@code text} shows it; whether it did. */
    private boolean detect(String text) {
        if ((lineNumber == 1 && text.trim().equals("1")) || text.contains(SaveFileLayout.START_MARK)) {
            layout = new SaveFileLayout(records, problems, recent, lineNumber);
        } else if (text.contains("intercepted") || text.contains("received")) {
            if (ConsoleLayout.isHeader(text)) {
                layout = new ConsoleLayout(records, problems);
            } else if (text.strip().endsWith(":")) {
                layout = new ColumnsLayout(records, problems);
            }
        }
        return layout != null;
    }

    /**
     * A line longer than the reader's cap was skipped: it counts as a line, is reported as an error, and breaks
     * the record in progress if there is one.
     *
     * @param bytes the skipped line's length in bytes
     */
    public void acceptOverlongLine(long bytes) {
        lineNumber++;
        if (layout == null) {
            recent.push("");
            problems.accept(new ParseProblem(lineNumber, ParseProblem.Severity.ERROR,
                    "line of " + bytes + " bytes is longer than the limit and was skipped"));
            return;
        }
        layout.overlongLine(lineNumber, bytes);
    }

    /** The input is over (batch mode): a record still in progress is reported once as a WARNING. */
    public void endOfInput() {
        if (layout != null) {
            layout.endOfInput();
        }
    }

    /** Forgets the record in progress and restarts line numbering (the file was truncated or replaced). */
    public void reset() {
        lineNumber = 0;
        layout = null;
        recent.clear();
        yarpLines = 0;
    }

    /** The number of lines seen since construction or the last {@link #reset()}. */
    public long lineNumber() {
        return lineNumber;
    }

    /**
     * How many of the lines before the first record header (since construction or the last {@link #reset()}) were
     * YARP's own about the monitor's port ({@code Port /monitor active at ...}): what a monitor prints before the
     * robot's first message.
     */
    public long yarpLines() {
        return yarpLines;
    }

    /** What the records' times count, once the layout is known: ticks for a console capture, else seconds. */
    public Clock clock() {
        return layout instanceof ConsoleLayout ? Clock.TICKS : Clock.SECONDS;
    }

    /**
     * This parser as a {@link LineSink}: lines are {@link #acceptLine accepted}, overlong lines reported, and a
     * restart first reports a record left in progress (as {@link #endOfInput()} does) then {@link #reset()}s, and
     * the end of the file is {@link #endOfInput()}.
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
            public void lastLine(byte[] bytes, int offset, int length) {
                acceptLastLine(new String(bytes, offset, length, StandardCharsets.UTF_8));
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

            @Override
            public void ended() {
                endOfInput();
            }
        };
    }
}
