package dev.predmon.parse;

import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Consumer;

/** Reads a whole log file once, streaming, into records. */
public final class LogReader {
    private LogReader() {
    }

    /** Parses {@code file} line by line; returns the number of records emitted. */
    public static long read(Path file, Consumer<LogRecord> records, Consumer<ParseProblem> problems) throws IOException {
        throw new UnsupportedOperationException("TODO parser");
    }
}
