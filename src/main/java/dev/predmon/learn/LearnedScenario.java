package dev.predmon.learn;

import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.mealy.MealyTrace;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.List;
import java.util.Map;

/**
 * What learning made of one scenario.
 *
 * @param spec     the scenario
 * @param machines one machine per conflict-free group of its runs
 * @param splits   for each machine after the first, the conflict that forced it
 * @param skipped  logs that gave no interface message at all, with why
 * @param problems parse problems of its logs, formatted {@code file:line: severity: message}
 * @param unmapped interface messages no abstraction rule maps, by key, over all its logs
 */
public record LearnedScenario(ScenarioSpec spec, List<Machine> machines, List<Conflict> splits, List<String> skipped,
                              List<String> problems, Map<UnmappedMessage, Long> unmapped) {

    /**
     * One machine and the samples it was learned from.
     *
     * @param id      file stem
     * @param machine the learned machine
     * @param samples its samples
     * @param millis  learning time
     */
    public record Machine(String id, CompactMealy<String, String> machine, List<MealyTrace> samples, long millis) {
    }
}
