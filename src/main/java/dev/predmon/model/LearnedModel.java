package dev.predmon.model;

import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.transducer.CompactMealy;

/**
 * One learned Mealy machine of a scenario.
 *
 * @param id       the file stem: {@code recharge}, or {@code recharge-2} when the scenario needed several
 * @param scenario the scenario it belongs to
 * @param faulty   whether that scenario violates the safety property
 * @param machine  the machine, over the full {@code alphabet}
 * @param alphabet every input symbol of the abstraction plus {@code Delta}, sorted
 */
public record LearnedModel(String id, String scenario, boolean faulty, CompactMealy<String, String> machine,
                           Alphabet<String> alphabet) {
}
