package dev.predmon.parse;

import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The monitor's console output redirected to a file, the commonest real form: YARP prints each message as
 * {@code [LEVEL] text} with ANSI colour codes around the level ({@code ESC[01;32mDEBUGESC[00m] Command
 * intercepted:}) and no time stamp anywhere. A record is a {@code <Kind> intercepted:} (or older {@code Message
 * received:}) header followed by its field lines; YARP's own {@code [INFO] |yarp.os.Port| ...} lines and other
 * programs' output (a Qt inspector announcing the port it listens on, say) between records are skipped.
 *
 * <p>With no time stamps, the run's clock is the tree's tick: every record's time is the number of the last
 * {@code Tick} record before it (0 before the first), and a tick record's time is its own number, its
 * {@code Arguments} field. Records say so with {@link Clock#TICKS}.
 *
 * <p>A header is recognised after removing colour codes (also ones whose escape character was lost, as in a
 * capture cut mid-sequence); text before the level tag, from another program writing to the same terminal without
 * a newline, does not hide it. A line ending like a header whose prefix is not a level tag is reported.
 */
final class ConsoleLayout extends RecordLayout {

    private static final String LEVEL = "(TRACE|DEBUG|INFO|WARNING|ERROR|FATAL)";
    /** A colour code. */
    private static final Pattern ANSI = Pattern.compile("\u001b\\[[0-9;]*m");
    /** A colour code, or what is left of one whose escape character was lost: only for header lines. */
    private static final Pattern ANSI_LENIENT = Pattern.compile("\u001b?\\[[0-9;]*m");
    /** A header once colour codes are removed: an optional prefix, the level tag, the header text. */
    static final Pattern HEADER = Pattern.compile("(.*?)\\[?[ \\t]*" + LEVEL + "[ \\t]*\\][ \\t]*"
            + ColumnsLayout.HEADER_TEXT);
    private static final Pattern HEADER_SUFFIX = Pattern.compile("(?:^|\\s|\\])" + ColumnsLayout.HEADER_TEXT + "$");

    /** The number of the last tick record: the clock of the records after it. */
    private double tick;

    ConsoleLayout(Consumer<LogRecord> records, Consumer<ParseProblem> problems) {
        super(records, problems);
    }

    /** {@code text} without its colour codes, also those whose escape character was lost. */
    static String withoutColours(String text) {
        return ANSI_LENIENT.matcher(text).replaceAll("");
    }

    /** Whether {@code text} is a record header of this layout: what makes the parser read a log as a console capture. */
    static boolean isHeader(String text) {
        return HEADER.matcher(ANSI_LENIENT.matcher(text).replaceAll("")).matches();
    }

    @Override
    LogRecord build(RecordDraft done) {
        LogRecord r = done.build(tick, Clock.TICKS);
        if (r.kind() == RecordKind.TICK) {
            double number = tickNumber(r.arguments());
            if (!Double.isNaN(number)) {
                tick = number;
                return done.build(tick, Clock.TICKS);
            }
        }
        return r;
    }

    @Override
    public void line(String text, long number) {
        lineNumber = number;
        if (draft != null) {
            String field = text.indexOf('\u001b') >= 0 ? ANSI.matcher(text).replaceAll("") : text;
            if (offerFieldLine(field)) {
                return;
            }
            notAField(field);
        }
        if (text.indexOf("intercepted") < 0 && text.indexOf("received") < 0) {
            return; // another program's line, or YARP's own: not a record
        }
        String plain = ANSI_LENIENT.matcher(text).replaceAll("");
        Matcher header = HEADER.matcher(plain);
        if (header.matches()) {
            draft = new RecordDraft(number, tick, header.group(2), header.group(3));
            return;
        }
        Matcher suffix = HEADER_SUFFIX.matcher(plain);
        if (suffix.find()) {
            String expected = suffix.group().startsWith("]") ? suffix.group().substring(1) : suffix.group();
            error(number, "malformed record header: expected '[DEBUG] " + expected.strip() + "', got " + quote(plain));
        }
    }

    /** Field lines of the record in progress from bytes; outside a record, lines that cannot start one undecoded. */
    @Override
    public boolean fastLine(byte[] b, int offset, int len, long number) {
        lineNumber = number;
        if (draft != null) {
            return fastField(b, offset, len);
        }
        return !mayBeHeader(b, offset, offset + len);
    }

    /** A tick record's number, or NaN when its Arguments field holds none. */
    private static double tickNumber(String arguments) {
        try {
            double n = Double.parseDouble(arguments);
            return Double.isFinite(n) ? n : Double.NaN;
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }
}
