package dev.predmon.mealy;

import net.automatalib.alphabet.Alphabets;
import net.automatalib.automaton.transducer.CompactMealy;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A pair as two Mealy steps. */
class MealyMappingTest {

    /** level_i answered o_high from the initial state; goTo_i is in the alphabet but was never seen there. */
    private static CompactMealy<String, String> machine() {
        CompactMealy<String, String> m = new CompactMealy<>(Alphabets.fromList(
                java.util.List.of("level_i", "goTo_i", MealyMapping.DELTA)));
        int q0 = m.addInitialState();
        int q1 = m.addState();
        int q2 = m.addState();
        m.addTransition(q0, "level_i", q1, MealyMapping.OK);
        m.addTransition(q1, MealyMapping.DELTA, q2, "o_high");
        return m;
    }

    @Test
    void aPairTheMachineTakesLeadsOnAndOneItDoesNotTakeLeadsNowhere() {
        CompactMealy<String, String> m = machine();
        int q0 = m.getIntInitialState();
        int q2 = MealyMapping.pairStep(m, q0, "level_i", "o_high");
        assertTrue(q2 >= 0);
        assertEquals(-1, MealyMapping.pairStep(m, q0, "level_i", "o_low"), "another reply");
        assertEquals(-1, MealyMapping.pairStep(m, q0, "goTo_i", "o_goto"), "no transition");
        assertEquals(-1, MealyMapping.pairStep(m, q0, "unknown_i", "o_x"), "not in the alphabet");
        assertEquals(-1, MealyMapping.pairStep(m, q2, "level_i", "o_high"), "nothing seen after the first pair");
    }
}
