package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.compact.IoPair;

import java.util.HashMap;
import java.util.Map;

/**
 * Gives each compacted pair its Mealy input symbol: the query's input symbol, or, for queries whose rule carries
 * its answer, the symbol with the query's previous answer ({@link Abstraction#mealyInput}). It remembers the last
 * answer of each query, which is why it lives in the one shared pipeline: learn and watch must carry identically.
 */
final class CarryEncoder {

    private final Abstraction abstraction;
    private final Map<String, String> lastAnswer = new HashMap<>();

    CarryEncoder(Abstraction abstraction) {
        this.abstraction = abstraction;
    }

    /** The pair with its Mealy input; remembers its answer for the query's next pair. */
    IoPair encode(IoPair pair) {
        String previous = lastAnswer.put(pair.input(), pair.output());
        String input = abstraction.mealyInput(pair.input(), previous);
        return input.equals(pair.input()) ? pair : new IoPair(input, pair.output(), pair.command(), pair.reply());
    }

    /** Forgets every answer (the log was truncated or replaced). */
    void reset() {
        lastAnswer.clear();
    }
}
