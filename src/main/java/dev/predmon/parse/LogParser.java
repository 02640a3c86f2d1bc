package dev.predmon.parse;

import java.util.function.Consumer;

/**
 * Push parser for YARP monitor logs: fed one physical line at a time, it emits each complete record once.
 * Constant memory: it holds at most one record in progress.
 */
public final class LogParser {

    /** @param records receives every complete record; @param problems receives broken or truncated records */
    public LogParser(Consumer<LogRecord> records, Consumer<ParseProblem> problems) {
        throw new UnsupportedOperationException("TODO parser");
    }

    /** Feeds one line without its terminator (a trailing {@code '\r'} is tolerated). */
    public void acceptLine(String line) {
        throw new UnsupportedOperationException("TODO parser");
    }

    /** The input is over (batch mode): a record still in progress is reported once as a WARNING. */
    public void endOfInput() {
        throw new UnsupportedOperationException("TODO parser");
    }

    /** Forgets the record in progress and restarts line numbering (the file was truncated or replaced). */
    public void reset() {
        throw new UnsupportedOperationException("TODO parser");
    }
}
