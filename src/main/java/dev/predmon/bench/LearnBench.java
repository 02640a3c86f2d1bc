package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.Traces;
import dev.predmon.simulate.Scenario;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

/**
 * Learning time and peak heap for N runs per scenario: the samples are prepared first (simulated, printed,
 * parsed, compacted: not timed), then the three scenarios are learned as {@code learn} learns them
 * ({@link ScenarioLearner#learnSamples}: conflict grouping, one BlueFringeRPNIMealy per group). Peak heap is the
 * sum of the heap pools' peaks since the start of learning (after a GC), samples included.
 */
final class LearnBench {

    /**
     * @param runs     runs per scenario
     * @param seconds  learning time of all three scenarios
     * @param peakMb   peak heap during learning, MB
     * @param states   states of all machines learned
     * @param machines machines learned
     * @param prepareSeconds time to simulate and read the samples (not part of {@code seconds})
     */
    record Result(int runs, double seconds, double peakMb, int states, int machines, double prepareSeconds) {
    }

    /**
     * @param logs           logs read
     * @param bytes          their total size
     * @param threads        threads of the parallel reading (the machine's cores)
     * @param oneSeconds     reading every log on one thread (median of the rounds)
     * @param allSeconds     reading them on {@code threads} threads (median of the rounds)
     * @param identical      whether the models learned from both readings are byte-identical
     * @param prepareSeconds time to simulate and write the logs (not part of either)
     */
    record Speedup(int logs, long bytes, int threads, double oneSeconds, double allSeconds, boolean identical,
                   double prepareSeconds) {
        double factor() {
            return oneSeconds / allSeconds;
        }
    }

    static final int ROUNDS = 3;

    private LearnBench() {
    }

    /**
     * What {@code learn} spends its time on, reading (parse, abstract, compact) {@code runs} logs per scenario, timed
     * on one thread and on every core ({@link Traces#readAll}); then the three scenarios are learned from each
     * reading and their models compared byte for byte. A warm-up pass over a tenth of the logs comes first; then
     * {@value #ROUNDS} rounds of both, alternated, of which the medians are reported.
     */
    static Speedup speedup(Abstraction abstraction, int runs, Path dir) throws Exception {
        long prep = System.nanoTime();
        Path logs = Files.createTempDirectory(dir, "predmon-learn");
        try {
            Map<Scenario, List<Path>> byScenario = new EnumMap<>(Scenario.class);
            List<Path> all = new ArrayList<>();
            long bytes = 0;
            for (Scenario s : Scenario.values()) {
                List<Path> list = new ArrayList<>();
                for (long seed = 1; seed <= runs; seed++) {
                    Path log = logs.resolve(s.id() + "-" + seed + ".log");
                    Files.writeString(log, BenchData.text(s, seed));
                    bytes += Files.size(log);
                    list.add(log);
                }
                byScenario.put(s, list);
                all.addAll(list);
            }
            double prepareSeconds = (System.nanoTime() - prep) / 1e9;
            int threads = Runtime.getRuntime().availableProcessors();
            Traces.readAll(all.subList(0, Math.max(1, all.size() / 10)), abstraction, threads);
            Map<Path, LogTrace> one = null;
            Map<Path, LogTrace> parallel = null;
            double[] oneTimes = new double[ROUNDS];
            double[] allTimes = new double[ROUNDS];
            for (int i = 0; i < ROUNDS; i++) { // alternated, so that both see the same load and JIT state
                long start = System.nanoTime();
                one = Traces.readAll(all, abstraction, 1);
                oneTimes[i] = (System.nanoTime() - start) / 1e9;
                start = System.nanoTime();
                parallel = Traces.readAll(all, abstraction, threads);
                allTimes[i] = (System.nanoTime() - start) / 1e9;
            }
            Arrays.sort(oneTimes);
            Arrays.sort(allTimes);
            double oneSeconds = BatchBench.median(oneTimes);
            double allSeconds = BatchBench.median(allTimes);
            boolean identical = models(byScenario, abstraction, one).equals(models(byScenario, abstraction, parallel));
            return new Speedup(all.size(), bytes, threads, oneSeconds, allSeconds, identical, prepareSeconds);
        } finally {
            try (Stream<Path> files = Files.list(logs)) {
                for (Path f : files.toList()) {
                    Files.delete(f);
                }
            }
            Files.delete(logs);
        }
    }

    /** The DOT text of every machine learned from {@code traces}, as {@code learn} writes them. */
    private static Map<String, String> models(Map<Scenario, List<Path>> logs, Abstraction abstraction,
                                              Map<Path, LogTrace> traces) throws Exception {
        List<LearnedScenario> learned = new ArrayList<>();
        for (Scenario s : Scenario.values()) {
            learned.add(ScenarioLearner.learn(new ScenarioSpec(s.id(), s.faulty(), s.description(), logs.get(s)),
                    abstraction, traces));
        }
        return LearnedModels.dots(learned, MealyAlphabet.inputs(abstraction));
    }

    static Result run(Abstraction abstraction, int runs) {
        long prep = System.nanoTime();
        Map<Scenario, List<MealyTrace>> samples = new EnumMap<>(Scenario.class);
        for (Scenario s : Scenario.values()) {
            List<MealyTrace> list = new ArrayList<>(runs);
            for (long seed = 1; seed <= runs; seed++) {
                list.add(BenchData.sample(BenchData.text(s, seed), abstraction, s.id() + "-" + seed + ".log"));
            }
            samples.put(s, list);
        }
        double prepareSeconds = (System.nanoTime() - prep) / 1e9;
        System.gc();
        List<MemoryPoolMXBean> heap = ManagementFactory.getMemoryPoolMXBeans().stream()
                .filter(p -> p.getType() == MemoryType.HEAP).toList();
        heap.forEach(MemoryPoolMXBean::resetPeakUsage);
        long start = System.nanoTime();
        int states = 0;
        int machines = 0;
        for (Scenario s : Scenario.values()) {
            var learned = ScenarioLearner.learnSamples(new ScenarioSpec(s.id(), s.faulty(), s.description(), List.of()),
                    samples.get(s), MealyAlphabet.inputs(abstraction));
            for (var m : learned.machines()) {
                states += m.machine().size();
                machines++;
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        double peak = heap.stream().mapToLong(p -> p.getPeakUsage().getUsed()).sum() / 1e6;
        return new Result(runs, seconds, peak, states, machines, prepareSeconds);
    }
}
