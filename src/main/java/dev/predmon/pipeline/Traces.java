package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.SafetyRule;
import dev.predmon.compact.IoPair;
import dev.predmon.parse.LogReader;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

/** Reads whole logs offline through the shared {@link TracePipeline}. */
public final class Traces {

    /** At most this many parse problems are kept per log; the rest are only counted by the parser. */
    public static final int MAX_PROBLEMS = 100;

    private Traces() {
    }

    /** Parses, abstracts and compacts {@code log}, cut into its runs; each run says whether it violated the property. */
    public static LogTrace read(Path log, Abstraction abstraction) throws IOException {
        List<IoPair> pairs = new ArrayList<>();
        List<ParseProblem> problems = new ArrayList<>();
        RunCollector runs = new RunCollector(abstraction, pairs);
        TracePipeline pipeline = new TracePipeline(abstraction, runs);
        LogReader.read(log, pipeline::accept, p -> {
            if (problems.size() < MAX_PROBLEMS) {
                problems.add(p);
            }
        });
        pipeline.endOfInput();
        return new LogTrace(log, List.copyOf(pairs), List.copyOf(problems), pipeline.records(),
                pipeline.interfaceRecords(), pipeline.unmapped(), runs.runs());
    }

    /** Collects each run's pairs and whether the safety monitor saw it violate the property. */
    private static final class RunCollector implements PipelineListener {
        private final Optional<SafetyRule> safety;
        private Map<String, List<Double>> readings = new TreeMap<>();
        private final List<IoPair> all;
        private final List<LogTrace.Run> done = new ArrayList<>();
        private List<IoPair> pairs = new ArrayList<>();
        private long firstLine = 1;
        private boolean violated;

        RunCollector(Abstraction abstraction, List<IoPair> all) {
            this.safety = abstraction.safety();
            this.all = all;
        }

        @Override
        public void record(LogRecord record) {
            violated |= safety.isPresent() && safety.get().violatedBy(safety.get().valueOf(record));
        }

        @Override
        public void reading(String input, double value) {
            readings.computeIfAbsent(input, k -> new ArrayList<>()).add(value);
        }

        @Override
        public void pair(IoPair pair, LogRecord trigger) {
            pairs.add(pair);
            all.add(pair);
        }

        @Override
        public void runStarted(int run, LogRecord first) {
            finish();
            firstLine = first.line();
        }

        private void finish() {
            Map<String, List<Double>> frozen = new TreeMap<>();
            readings.forEach((k, v) -> frozen.put(k, List.copyOf(v)));
            done.add(new LogTrace.Run(done.size(), firstLine, List.copyOf(pairs), violated,
                    java.util.Collections.unmodifiableMap(frozen)));
            pairs = new ArrayList<>();
            readings = new TreeMap<>();
            violated = false;
        }

        List<LogTrace.Run> runs() {
            finish();
            return List.copyOf(done);
        }
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
