package dev.predmon.parse;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;

/**
 * Reads a whole log file once, streaming, into records.
 *
 * <p>Bytes are cut into lines by {@link LineSplitter}: UTF-8 with malformed input replaced, {@code \n} or
 * {@code \r\n} endings, a last line without newline still a line, lines over 1 MiB reported and skipped without
 * being held. Memory does not grow with the file.
 */
public final class LogReader {

    private static final int BUFFER_BYTES = 64 * 1024;

    private LogReader() {
    }

    /**
     * Parses {@code file} line by line, ending with {@link LogParser#endOfInput()}; returns the number of
     * records emitted.
     *
     * @throws IOException only when the file cannot be read (missing, unreadable, I/O failure); bad content is
     *                     reported to {@code problems}
     */
    public static long read(Path file, Consumer<LogRecord> records, Consumer<ParseProblem> problems) throws IOException {
        long[] count = {0};
        LogParser parser = new LogParser(record -> {
            count[0]++;
            records.accept(record);
        }, problems);
        LineSplitter splitter = new LineSplitter(LineSplitter.DEFAULT_MAX_LINE_BYTES, parser.lineSink());
        try (InputStream in = Files.newInputStream(file)) {
            byte[] buffer = new byte[BUFFER_BYTES];
            for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                splitter.feed(buffer, 0, n);
            }
        }
        splitter.finish();
        parser.endOfInput();
        return count[0];
    }
}
