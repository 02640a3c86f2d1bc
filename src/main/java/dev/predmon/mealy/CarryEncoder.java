package dev.predmon.mealy;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.compact.IoPair;

import java.util.HashMap;
import java.util.Map;
import java.util.Set;

/**
 * Gives each compacted pair its Mealy input symbol: the query's input symbol, or, for a query whose rule carries
 * its answer ({@link Abstraction#carriedAnswers()}), the symbol with the query's previous answer
 * ({@link MealyAlphabet#carried}). It remembers the last answer of each query, which is why one instance lives in
 * the one shared pipeline: learn and watch must carry identically.
 *
 * <p>Why: in the thesis's I/O-automaton-to-Mealy mapping a Mealy state follows inputs only, so to predict the
 * next battery band a machine must count {@code level_i} queries, entangled with every navigation event around
 * them; each new interleaving is then a path no training run took. Carrying the current band in the query lets a
 * band change be the same transition wherever it happens, which generalises across timing.
 */
public final class CarryEncoder {

    private final Set<String> carried;
    private final Map<String, String> lastAnswer = new HashMap<>();

    public CarryEncoder(Abstraction abstraction) {
        this.carried = Set.copyOf(abstraction.carriedAnswers().keySet());
    }

    /** The pair with its Mealy input; remembers its answer for the query's next pair. */
    public IoPair encode(IoPair pair) {
        String previous = lastAnswer.put(pair.input(), pair.output());
        if (previous == null || !carried.contains(pair.input())) {
            return pair;
        }
        return new IoPair(MealyAlphabet.carried(pair.input(), previous), pair.output(), pair.command(), pair.reply());
    }

    /** Forgets every answer (the log was truncated or replaced). */
    public void reset() {
        lastAnswer.clear();
    }
}
