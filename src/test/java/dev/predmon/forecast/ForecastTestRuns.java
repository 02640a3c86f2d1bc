package dev.predmon.forecast;

import dev.predmon.compact.IoPair;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.alphabet.Alphabets;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** Hand-made machines and runs for the forecast's tests: pairs {@code a/x}, {@code b/y}, {@code c/z}. */
final class ForecastTestRuns {

    static final Alphabet<String> ALPHABET = Alphabets.fromList(List.of("a", "b", "c", MealyMapping.DELTA));

    private ForecastTestRuns() {
    }

    /**
     * A machine of the pairs a/x then b/y then (c/z)*: states 0 -a-> 1 -Delta-> 2 -b-> 3 -Delta-> 4 -c-> 5 -Delta-> 4.
     * Pair states: 0 (start), 2 (after a), 4 (after b and every c).
     */
    static CompactMealy<String, String> chain() {
        CompactMealy<String, String> m = new CompactMealy<>(ALPHABET);
        int[] s = new int[6];
        for (int i = 0; i < 6; i++) {
            s[i] = i == 0 ? m.addInitialState() : m.addState();
        }
        m.addTransition(s[0], "a", s[1], MealyMapping.OK);
        m.addTransition(s[1], MealyMapping.DELTA, s[2], "x");
        m.addTransition(s[2], "b", s[3], MealyMapping.OK);
        m.addTransition(s[3], MealyMapping.DELTA, s[4], "y");
        m.addTransition(s[4], "c", s[5], MealyMapping.OK);
        m.addTransition(s[5], MealyMapping.DELTA, s[4], "z");
        return m;
    }

    static Map<String, CompactMealy<String, String>> machines() {
        return Map.of("chain", chain());
    }

    /**
     * A run of the given pairs ("a/x" ...), one per second from t=0, the property reading {@code values[i]} at pair i;
     * it violates at {@code violation} (NaN: never) and ends one second after its last pair.
     */
    static LogTrace.Run run(List<String> pairs, double[] values, double violation) {
        List<IoPair> io = new ArrayList<>();
        double[] times = new double[pairs.size()];
        List<RunTiming.Reading> readings = new ArrayList<>();
        double low = Double.NaN;
        for (int i = 0; i < pairs.size(); i++) {
            String[] p = pairs.get(i).split("/", -1);
            io.add(new IoPair(p[0], p[1], null, null));
            times[i] = i;
            readings.add(new RunTiming.Reading(i, values[i], i));
            if ((Double.isNaN(violation) || i < violation) && !(values[i] >= low)) {
                low = values[i];
            }
        }
        RunTiming t = new RunTiming(times, values, violation, pairs.size(), low, "s", readings);
        return new LogTrace.Run(0, 1, io, !Double.isNaN(violation), Map.of(), t);
    }
}
