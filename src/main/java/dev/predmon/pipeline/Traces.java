package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.Classification;
import dev.predmon.compact.IoPair;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.Verdict;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Consumer;

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
        long lines;
        try (RecordSource source = abstraction.format().read(log, RecordSink.of(pipeline::accept, p -> {
            if (problems.size() < MAX_PROBLEMS) {
                problems.add(p);
            }
        }))) {
            source.drain();
            lines = source.lines();
        }
        pipeline.endOfInput();
        return new LogTrace(log, List.copyOf(pairs), List.copyOf(problems), lines, pipeline.records(),
                pipeline.interfaceRecords(), pipeline.unmapped(), runs.runs(), pipeline.span());
    }

    /** A log that could not be read, with the reason ({@link #getCause()}). */
    public static final class ReadFailure extends IOException {
        private final Path log;

        ReadFailure(Path log, IOException cause) {
            super(cause.getMessage(), cause);
            this.log = log;
        }

        public Path log() {
            return log;
        }
    }

    /** {@link #readAll(Collection, Abstraction, int, Consumer)} on every core. */
    public static Map<Path, LogTrace> readAll(Collection<Path> logs, Abstraction abstraction) throws ReadFailure {
        return readAll(logs, abstraction, Runtime.getRuntime().availableProcessors(), log -> {
        });
    }

    /** {@link #readAll(Collection, Abstraction, int, Consumer)} without progress. */
    public static Map<Path, LogTrace> readAll(Collection<Path> logs, Abstraction abstraction, int threads)
            throws ReadFailure {
        return readAll(logs, abstraction, threads, log -> {
        });
    }

    /**
     * {@link #read Reads} each distinct log once, {@code threads} logs at a time, into a map in the order of
     * {@code logs}. Each log's trace depends on that log alone, so the result is the same whatever the thread count:
     * what is learned from it stays deterministic. Reading (parse, abstract, compact) is what {@code learn} and
     * {@code evaluate} spend their time on; logs are independent, so it is spread over the cores.
     *
     * @param read receives each log once its trace is in, on the calling thread and in the order of {@code logs}
     *             (for progress)
     * @throws ReadFailure for the first log, in the order of {@code logs}, that could not be read
     */
    public static Map<Path, LogTrace> readAll(Collection<Path> logs, Abstraction abstraction, int threads,
                                              Consumer<Path> read) throws ReadFailure {
        List<Path> distinct = new ArrayList<>(new LinkedHashSet<>(logs));
        Map<Path, LogTrace> traces = new LinkedHashMap<>();
        if (threads <= 1 || distinct.size() <= 1) {
            for (Path log : distinct) {
                traces.put(log, readOne(log, abstraction));
                read.accept(log);
            }
            return traces;
        }
        ExecutorService pool = Executors.newFixedThreadPool(Math.min(threads, distinct.size()), task -> {
            Thread t = new Thread(task, "predmon-read");
            t.setDaemon(true);
            return t;
        });
        try {
            List<Future<LogTrace>> pending = new ArrayList<>();
            for (Path log : distinct) {
                pending.add(pool.submit(() -> readOne(log, abstraction)));
            }
            for (int i = 0; i < distinct.size(); i++) {
                traces.put(distinct.get(i), pending.get(i).get());
                read.accept(distinct.get(i));
            }
            return traces;
        } catch (ExecutionException e) {
            if (e.getCause() instanceof ReadFailure f) {
                throw f;
            }
            if (e.getCause() instanceof RuntimeException r) {
                throw r;
            }
            if (e.getCause() instanceof Error err) {
                throw err;
            }
            throw new IllegalStateException(e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new CancellationException("interrupted while reading logs");
        } finally {
            pool.shutdownNow();
        }
    }

    private static LogTrace readOne(Path log, Abstraction abstraction) throws ReadFailure {
        try {
            return read(log, abstraction);
        } catch (ReadFailure e) {
            throw e;
        } catch (IOException e) {
            throw new ReadFailure(log, e);
        }
    }

    /** Collects each run's pairs and whether the safety monitor saw it violate the property. */
    private static final class RunCollector implements PipelineListener {
        private final Abstraction abstraction;
        private final Optional<Bound> safety;
        private Map<String, List<Double>> readings = new TreeMap<>();
        private final List<IoPair> all;
        private final List<LogTrace.Run> done = new ArrayList<>();
        private List<IoPair> pairs = new ArrayList<>();
        private long firstLine = 1;
        private boolean violated;
        private double value = Double.NaN;
        private double lowestSafe = Double.NaN;
        private double violationTime = Double.NaN;
        private double endTime = Double.NaN;
        private String unit = "s";
        private List<RunTiming.Reading> changes = new ArrayList<>();
        private List<RunTiming.Gap> gaps = new ArrayList<>();
        private double[] times = new double[64];
        private double[] values = new double[64];
        /** The safety monitor's obligations, for the deadline forecast. */
        private final PropertyChecker checker;
        /** The safety property's position among the checked ones, or -1. */
        private final int safetyIndex;
        private List<RunTiming.Obligation> obligations = new ArrayList<>();
        /** Where each pending obligation began: its deadline forecast's condition. */
        private final TriggerInputs triggers;
        /** The run's outcome: when each property was first violated. */
        private Map<String, Double> violations = new TreeMap<>();
        /** By property index, the bound properties but the safety one: each change of their value in the run. */
        private final List<RunTiming.Reading>[] others;
        private final double[] otherValues;

        RunCollector(Abstraction abstraction, List<IoPair> all) {
            this.abstraction = abstraction;
            this.safety = abstraction.safety();
            this.all = all;
            this.checker = new PropertyChecker(abstraction.properties(),
                    (i, p, v) -> violations.putIfAbsent(p.id(), v.time()));
            this.safetyIndex = safety.map(b -> abstraction.properties().indexOf(b)).orElse(-1);
            List<Property> properties = abstraction.properties();
            @SuppressWarnings("unchecked")
            List<RunTiming.Reading>[] o = new List[properties.size()];
            this.others = o;
            this.otherValues = new double[properties.size()];
            for (int i = 0; i < others.length; i++) {
                if (properties.get(i) instanceof Bound && i != safetyIndex) {
                    others[i] = new ArrayList<>();
                }
            }
            Arrays.fill(otherValues, Double.NaN);
            this.triggers = new TriggerInputs(abstraction, properties);
            checker.onObligations((i, p, line, duration, discharged) -> {
                obligations.add(new RunTiming.Obligation(p.id(), duration, discharged, triggers.began(i, line)));
                triggers.closed(i, line);
            });
        }

        @Override
        public void record(LogRecord record) {
            checker.accept(record);
            triggers.record(checker, record);
            if (!Double.isNaN(record.time())) {
                endTime = record.time();
            }
            unit = record.clock().unit();
            for (int i = 0; i < others.length; i++) {
                // as the checker read it within the property's scope: a value outside it neither violates the
                // property nor tells how low its safe runs went
                double b = others[i] == null ? Double.NaN : checker.reading(i);
                if (!Double.isNaN(b) && b != otherValues[i]) {
                    others[i].add(new RunTiming.Reading(record.time(), b, pairs.size()));
                    otherValues[i] = b;
                }
            }
            if (safety.isEmpty()) {
                return;
            }
            // The checker is the judge: the reading within the property's scope, and its verdict (its listener)
            double v = checker.reading(safetyIndex);
            if (Double.isNaN(v)) {
                return;
            }
            if (v != value) {
                changes.add(new RunTiming.Reading(record.time(), v, pairs.size()));
            }
            value = v;
            Double at = violations.get(safety.get().id());
            if (at != null) {
                if (!violated) {
                    violationTime = at;
                }
                violated = true;
            } else if (!(v >= lowestSafe)) {
                lowestSafe = v;
            }
        }

        @Override
        public void mapped(LogRecord record, Classification.Mapped c) {
            String input = abstraction.continuousInput(c);
            double value = c.event().value();
            if (input != null && !Double.isNaN(value)) {
                List<Double> values = readings.get(input);
                if (values == null) {
                    values = new ArrayList<>();
                    readings.put(input, values);
                }
                values.add(value);
            }
        }

        @Override
        public void gap(LogRecord record) {
            gaps.add(new RunTiming.Gap(record.line(), pairs.size()));
        }

        @Override
        public void pair(IoPair pair, LogRecord trigger) {
            int i = pairs.size();
            if (i == times.length) {
                times = Arrays.copyOf(times, i * 2);
                values = Arrays.copyOf(values, i * 2);
            }
            times[i] = trigger.time();
            values[i] = value;
            pairs.add(pair);
            all.add(pair);
        }

        @Override
        public void runStarted(int run, LogRecord first) {
            checker.overdue(first); // a deadline that passed in the silence before it is the run's violation
            finish();
            firstLine = first.line();
        }

        private void finish() {
            Map<String, List<Double>> frozen = new TreeMap<>();
            readings.forEach((k, v) -> frozen.put(k, List.copyOf(v)));
            Set<String> unobserved = new TreeSet<>();
            for (int i = 0; i < abstraction.properties().size(); i++) {
                if (checker.verdict(i) instanceof Verdict.NoEvidence) {
                    unobserved.add(abstraction.properties().get(i).id());
                }
            }
            checker.finish();
            checker.reset();
            triggers.reset();
            Map<String, List<RunTiming.Reading>> bounds = new TreeMap<>();
            for (int i = 0; i < others.length; i++) {
                if (others[i] != null) {
                    bounds.put(abstraction.properties().get(i).id(), List.copyOf(others[i]));
                    others[i].clear();
                }
            }
            Arrays.fill(otherValues, Double.NaN);
            RunTiming timing = new RunTiming(Arrays.copyOf(times, pairs.size()), Arrays.copyOf(values, pairs.size()),
                    violationTime, endTime, lowestSafe, unit, changes, gaps, obligations, violations, bounds,
                    unobserved);
            changes = new ArrayList<>();
            gaps = new ArrayList<>();
            obligations = new ArrayList<>();
            violations = new TreeMap<>();
            done.add(new LogTrace.Run(done.size(), firstLine, List.copyOf(pairs), violated,
                    Collections.unmodifiableMap(frozen), timing));
            pairs = new ArrayList<>();
            readings = new TreeMap<>();
            violated = false;
            value = Double.NaN;
            lowestSafe = Double.NaN;
            violationTime = Double.NaN;
            endTime = Double.NaN;
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
