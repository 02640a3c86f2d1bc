package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelStore;
import dev.predmon.simulate.Scenario;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.util.ArrayList;
import java.util.List;

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

    private LearnBench() {
    }

    static Result run(Abstraction abstraction, int runs) {
        long prep = System.nanoTime();
        List<List<MealyTrace>> samples = new ArrayList<>();
        for (Scenario s : Scenario.values()) {
            List<MealyTrace> list = new ArrayList<>(runs);
            for (long seed = 1; seed <= runs; seed++) {
                list.add(BenchData.sample(BenchData.text(s, seed), abstraction, s.id() + "-" + seed + ".log"));
            }
            samples.add(list);
        }
        double prepareSeconds = (System.nanoTime() - prep) / 1e9;
        System.gc();
        List<MemoryPoolMXBean> heap = ManagementFactory.getMemoryPoolMXBeans().stream()
                .filter(p -> p.getType() == MemoryType.HEAP).toList();
        heap.forEach(MemoryPoolMXBean::resetPeakUsage);
        long start = System.nanoTime();
        int states = 0;
        int machines = 0;
        for (int i = 0; i < Scenario.values().length; i++) {
            Scenario s = Scenario.values()[i];
            var learned = ScenarioLearner.learnSamples(new ScenarioSpec(s.id(), s.faulty(), s.description(), List.of()),
                    samples.get(i), ModelStore.alphabetOf(abstraction));
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
