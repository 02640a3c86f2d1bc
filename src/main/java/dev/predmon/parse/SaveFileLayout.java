package dev.predmon.parse;

import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * yarplogger's own save file, as written by {@code LoggerEngine::save_all_logs_to_file} (robotology/yarp,
 * {@code src/libYARP_logger/src/yarp/logger/YarpLoggerFiles.cpp}): one value a line, empty strings written
 * {@code NULL-DATA}: version, number of ports, then per port its ip address, complete port name, prefix, system,
 * process name, pid, six level counters, log size and entry count, then per entry the yarprun time stamp, the local
 * time stamp, the level as a number (0 undefined, 1 TRACE ... 6 FATAL) and {@code <#STRING_START#>text<#STRING_END#>},
 * the text spanning lines when it has newlines (a monitor record's seven lines). Like yarplogger's own loader,
 * which searches for the next start marker, this does not count the per-port headers: the three lines before a
 * start marker are the entry's time stamps and level. The record's time is the local time stamp, or the yarprun
 * one when the local one is {@code NULL-DATA}.
 */
final class SaveFileLayout extends RecordLayout {

    static final String START_MARK = "<#STRING_START#>";
    private static final String END_MARK = "<#STRING_END#>";
    private static final String NULL_DATA = "NULL-DATA";
    /** yarplogger's {@code LogLevelEnum} in order. */
    private static final String[] SAVE_LEVELS = {"UNDEFINED", "TRACE", "DEBUG", "INFO", "WARNING", "ERROR", "FATAL"};
    private static final Pattern SAVE_LEVEL = Pattern.compile("\\d{1,9}");
    private static final Pattern TEXT_HEADER = Pattern.compile("\\s*" + ColumnsLayout.HEADER_TEXT);

    /** The line that made the parser read the input as a save file, for messages. */
    private final long saveSince;
    /** The last three value lines seen outside a text block. */
    private final RecentLines lastValues;
    private boolean inBlock;
    private boolean blockFirstLine;
    private long blockLine;
    private double blockTime;
    private String blockLevel;
    private boolean blockBroken;

    /**
     * @param lastValues the lines before {@code saveSince}, as the parser remembered them while it detected the layout
     * @param saveSince  the line that showed the input is a save file
     */
    SaveFileLayout(Consumer<LogRecord> records, Consumer<ParseProblem> problems, RecentLines lastValues,
                   long saveSince) {
        super(records, problems);
        this.lastValues = lastValues;
        this.saveSince = saveSince;
    }

    @Override
    LogRecord build(RecordDraft done) {
        return done.build();
    }

    @Override
    public void overlongLine(long number, long bytes) {
        super.overlongLine(number, bytes);
        blockFirstLine = false; // the skipped line cannot be an entry's header line any more
        lastValues.push("");
    }

    @Override
    public void endOfInput() {
        super.endOfInput();
        inBlock = false;
    }

    @Override
    public void line(String text, long number) {
        lineNumber = number;
        if (ColumnsLayout.HEADER.matcher(text).matches()) {
            // A text log's record in a file read as a save file (first line "1", or a start marker before any
            // record): its fields are not save-file values, so without this it would vanish silently.
            error(number, "record header of a text log inside a yarplogger save file (read as one because of "
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
            lastValues.push(text);
            blockText(text);
        } else if (start >= 0) {
            beginBlock();
            blockText(text.substring(start + START_MARK.length()));
        } else {
            lastValues.push(text);
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
        String time = localTime != null && ColumnsLayout.TIME.matcher(localTime).matches() ? localTime : yarprunTime;
        if (time == null || !ColumnsLayout.TIME.matcher(time).matches()) {
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
                draft = new RecordDraft(blockLine, blockTime, blockLevel, header.group(1));
            }
            return;
        }
        if (draft != null && !offerFieldLine(content)) {
            notAField(content);
        }
    }
}
