package dev.predmon.bench;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.learn.ForecastTraining;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.LogParser;
import dev.predmon.parse.LogRecord;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.Traces;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** Inputs of the benchmarks, all from the simulator: log texts, Mealy samples, models learned in memory. */
final class BenchData {

    private BenchData() {
    }

    /** The log text of one simulated run (default options). */
    static String text(Scenario s, long seed) {
        return LogWriter.toText(Simulator.run(s, seed, SimOptions.defaults()), SimOptions.defaults());
    }

    /** The records of a log text, parsed as any log is. */
    static List<LogRecord> records(String text) {
        List<LogRecord> records = new ArrayList<>();
        LogParser p = new LogParser(records::add, problem -> {
        });
        text.lines().forEach(p::acceptLine);
        p.endOfInput();
        return records;
    }

    /** The Mealy sample of a log text, as {@code learn} makes it. */
    static MealyTrace sample(String text, Abstraction abstraction, String source) {
        return MealyMapping.toTrace(Traces.compact(records(text), abstraction), source);
    }

    /**
     * The models of {@code learned} (from {@code runs} runs per scenario, seeds 1..runs, see {@link #learned}), with
     * their forecast as {@code learn} makes it (the runs written to a temporary directory and read back, as learn
     * reads logs).
     */
    static ModelSet models(Abstraction abstraction, List<LearnedScenario> learned, int runs) throws IOException {
        Path dir = Files.createTempDirectory("predmon-bench-models");
        try {
            List<ScenarioSpec> specs = new ArrayList<>();
            for (Scenario s : Scenario.values()) {
                List<Path> logs = new ArrayList<>();
                for (long seed = 1; seed <= runs; seed++) {
                    logs.add(Files.writeString(dir.resolve(s.id() + "-" + seed + ".log"), text(s, seed)));
                }
                specs.add(new ScenarioSpec(s.id(), s.faulty(), s.description(), List.copyOf(logs)));
            }
            Map<Path, LogTrace> traces = ScenarioLearner.read(specs.stream().flatMap(s -> s.logs().stream()).toList(),
                    abstraction);
            ForecastModel forecast = ForecastTraining.train(specs, traces, LearnedModels.machines(learned),
                    MealyAlphabet.inputs(abstraction), abstraction, abstraction.confirm());
            return LearnedModels.modelSet(learned, abstraction, forecast);
        } catch (BadInputException e) {
            throw new IOException(e.getMessage(), e);
        } finally {
            try (var files = Files.list(dir)) {
                for (Path p : files.toList()) {
                    Files.deleteIfExists(p);
                }
            }
            Files.deleteIfExists(dir);
        }
    }

    /** The three scenarios learned in memory from {@code runs} runs each (seeds 1..runs). */
    static List<LearnedScenario> learned(Abstraction abstraction, int runs) {
        List<LearnedScenario> learned = new ArrayList<>();
        for (Scenario s : Scenario.values()) {
            List<MealyTrace> samples = new ArrayList<>();
            for (long seed = 1; seed <= runs; seed++) {
                samples.add(sample(text(s, seed), abstraction, s.id() + "-" + seed + ".log"));
            }
            learned.add(ScenarioLearner.learnSamples(new ScenarioSpec(s.id(), s.faulty(), s.description(), List.of()),
                    samples, MealyAlphabet.inputs(abstraction)));
        }
        return learned;
    }

    /**
     * Writes a log of at least {@code bytes} bytes: runs of every scenario, seeds from 10,000 on, back to back
     * (each run's clock starts again near 0, which is how a run boundary is recognised).
     *
     * @return the number of runs written
     */
    static int bigLog(Path file, long bytes) throws IOException {
        // A pool of distinct runs, cycled: simulating is slower than what is measured and not what is measured.
        List<String> pool = new ArrayList<>();
        Scenario[] scenarios = Scenario.values();
        for (int i = 0; i < 12; i++) {
            pool.add(text(scenarios[i % scenarios.length], 10_000 + i));
        }
        long written = 0;
        int runs = 0;
        try (BufferedWriter w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            while (written < bytes) {
                String t = pool.get(runs % pool.size());
                w.write(t);
                written += t.length();
                runs++;
            }
        }
        return runs;
    }
}
