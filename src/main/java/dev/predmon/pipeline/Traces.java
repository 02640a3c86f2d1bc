package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.compact.IoPair;
import dev.predmon.parse.LogReader;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;

import java.io.IOException;
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

    /** Convenience for tests and tools: runs records already in memory through the pipeline. */
    public static List<IoPair> compact(Iterable<LogRecord> records, Abstraction abstraction) {
        List<IoPair> pairs = new ArrayList<>();
        TracePipeline pipeline = new TracePipeline(abstraction, (pair, trigger) -> pairs.add(pair));
        records.forEach(pipeline::accept);
        pipeline.endOfInput();
        return pairs;
    }
}
