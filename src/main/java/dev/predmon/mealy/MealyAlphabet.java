package dev.predmon.mealy;

import dev.predmon.abstraction.Abstraction;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.alphabet.MapAlphabet;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * The Mealy symbols of an abstraction: its input symbols, the carried inputs ({@link CarryEncoder}) and
 * {@value MealyMapping#DELTA} on the input side; its output symbols and {@value MealyMapping#OK} on the output side.
 */
public final class MealyAlphabet {

    private MealyAlphabet() {
    }

    /**
     * The Mealy input alphabet of models over {@code abstraction}, sorted: every input symbol, every carried query
     * after every answer its rule can give ({@link #carried}), and {@value MealyMapping#DELTA}.
     */
    public static Alphabet<String> inputs(Abstraction abstraction) {
        Set<String> symbols = new TreeSet<>(abstraction.inputAlphabet());
        for (Map.Entry<String, Set<String>> e : abstraction.carriedAnswers().entrySet()) {
            for (String answer : e.getValue()) {
                symbols.add(carried(e.getKey(), answer));
            }
        }
        symbols.add(MealyMapping.DELTA);
        // indexed by a map: every step of every model looks its input up (a list's linear search was 5% of
        // following 10,000 logs at robot pace)
        return new MapAlphabet<>(new ArrayList<>(symbols));
    }

    /** Every output a model over {@code abstraction} may give: the abstraction's output symbols and {@value MealyMapping#OK}. */
    public static Set<String> outputs(Abstraction abstraction) {
        Set<String> symbols = new HashSet<>(abstraction.outputAlphabet());
        symbols.add(MealyMapping.OK);
        return symbols;
    }

    /**
     * The Mealy input of a query whose rule carries its answer and that was answered before: the input symbol,
     * {@code _after_} and the previous answer ({@code level_i_after_o_level_medium_six}).
     */
    public static String carried(String input, String previousAnswer) {
        return input + "_after_" + previousAnswer;
    }
}
