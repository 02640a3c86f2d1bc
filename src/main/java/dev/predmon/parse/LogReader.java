package dev.predmon.parse;

import java.io.IOException;
import java.io.InputStream;
import java.io.InterruptedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.function.LongConsumer;

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
        return read(file, records, problems, lines -> { });
    }

    /** As {@link #read(Path, Consumer, Consumer)}; at the end {@code lines} gets the number of lines read. */
    public static long read(Path file, Consumer<LogRecord> records, Consumer<ParseProblem> problems,
                            LongConsumer lines) throws IOException {
        if (Files.size(file) < PARALLEL_FROM_BYTES) {
            return readHere(file, records, problems, lines);
        }
        return readAlongside(file, records, problems, lines);
    }

    /** Files from this size on are parsed on a second thread while the caller consumes the records. */
    static final long PARALLEL_FROM_BYTES = 8L << 20;
    private static final int CHUNK = 2048;
    private static final Object[] END = new Object[0];

    /** Parses on the calling thread. */
    static long readHere(Path file, Consumer<LogRecord> records, Consumer<ParseProblem> problems, LongConsumer lines)
            throws IOException {
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
        lines.accept(parser.lineNumber());
        return count[0];
    }

    /**
     * Parses on a second thread and hands records and problems over, in log order and in chunks, to the calling
     * thread, which runs the callbacks: on two cores parsing overlaps with what the caller does with each record
     * (abstraction, compaction, matching), and callers need no thread safety. A failure on either side stops both.
     */
    static long readAlongside(Path file, Consumer<LogRecord> records, Consumer<ParseProblem> problems,
                              LongConsumer lines) throws IOException {
        BlockingQueue<Object[]> queue = new ArrayBlockingQueue<>(8);
        AtomicLong lineCount = new AtomicLong();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread parser = new Thread(() -> {
            Object[][] chunk = {new Object[CHUNK]};
            int[] filled = {0};
            Consumer<Object> emit = o -> {
                chunk[0][filled[0]++] = o;
                if (filled[0] == CHUNK) {
                    handOver(queue, chunk[0]);
                    chunk[0] = new Object[CHUNK];
                    filled[0] = 0;
                }
            };
            try {
                readHere(file, emit::accept, emit::accept, lineCount::set);
                if (filled[0] > 0) {
                    handOver(queue, Arrays.copyOf(chunk[0], filled[0]));
                }
            } catch (Throwable e) {
                failure.set(e);
            } finally {
                try {
                    queue.put(END);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }, "predmon-parse");
        parser.setDaemon(true);
        parser.start();
        long count = 0;
        boolean done = false;
        try {
            for (Object[] c = queue.take(); c != END; c = queue.take()) {
                for (Object o : c) {
                    if (o instanceof LogRecord r) {
                        count++;
                        records.accept(r);
                    } else {
                        problems.accept((ParseProblem) o);
                    }
                }
            }
            done = true;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted while reading " + file);
        } finally {
            if (!done) {
                parser.interrupt(); // the caller failed or was interrupted: stop parsing
            }
        }
        Throwable e = failure.get();
        if (e instanceof IOException io) {
            throw io;
        }
        if (e instanceof RuntimeException re) {
            throw re;
        }
        if (e instanceof Error err) {
            throw err;
        }
        lines.accept(lineCount.get()); // set by the parser thread before its END, which the loop above took
        return count;
    }

    private static void handOver(BlockingQueue<Object[]> queue, Object[] chunk) {
        try {
            queue.put(chunk);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new CancellationException("the reader stopped");
        }
    }
}
