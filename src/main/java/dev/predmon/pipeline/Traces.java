package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.compact.IoPair;
import dev.predmon.parse.LogReader;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** Reads whole logs offline through the shared {@link TracePipeline}. */
public final class Traces {

    /** At most this many parse problems are kept per log; the rest are only counted by the parser. */
    public static final int MAX_PROBLEMS = 100;

    private Traces() {
    }

    /** Parses, abstracts and compacts {@code log}. */
    public static LogTrace read(Path log, Abstraction abstraction) throws IOException {
        List<IoPair> pairs = new ArrayList<>();
        List<ParseProblem> problems = new ArrayList<>();
        TracePipeline pipeline = new TracePipeline(abstraction, (pair, trigger) -> pairs.add(pair));
        LogReader.read(log, pipeline::accept, p -> {
            if (problems.size() < MAX_PROBLEMS) {
                problems.add(p);
            }
        });
        pipeline.endOfInput();
        return new LogTrace(log, List.copyOf(pairs), List.copyOf(problems), pipeline.records(),
                pipeline.interfaceRecords(), pipeline.unmapped());
    }

    /**
     * The lines of {@code log}, counted as the parser counts them (a last line without a newline is a line). Only
     * asked for when a log gave no record, to say how much was read.
     */
    public static long countLines(Path log) {
        long lines = 0;
        int last = '\n';
        try (InputStream in = Files.newInputStream(log)) {
            byte[] buffer = new byte[64 * 1024];
            for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                for (int i = 0; i < n; i++) {
                    if (buffer[i] == '\n') {
                        lines++;
                    }
                }
                if (n > 0) {
                    last = buffer[n - 1];
                }
            }
        } catch (IOException e) {
            return lines; // it was read a moment ago; what could be counted is the best answer
        }
        return last == '\n' ? lines : lines + 1;
    }

    /** Convenience for tests and tools: runs records already in memory through the pipeline. */
    public static List<IoPair> compact(Iterable<LogRecord> records, Abstraction abstraction) {
        List<IoPair> pairs = new ArrayList<>();
        TracePipeline pipeline = new TracePipeline(abstraction, (pair, trigger) -> pairs.add(pair));
        records.forEach(pipeline::accept);
        pipeline.endOfInput();
        return pairs;
    }
}
