package dev.predmon.mealy;

import net.automatalib.alphabet.Alphabets;
import net.automatalib.automaton.transducer.CompactMealy;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A pair as two Mealy steps, and the two ways a machine can fail to take it. */
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
    void aPairTheMachineTakesLeadsOnAndContradictsNothing() {
        CompactMealy<String, String> m = machine();
        int q0 = m.getIntInitialState();
        assertTrue(MealyMapping.pairStep(m, q0, "level_i", "o_high") >= 0);
        assertFalse(MealyMapping.contradicts(m, q0, "level_i", "o_high"));
    }

    @Test
    void anotherReplyToAKnownQueryIsAContradiction() {
        CompactMealy<String, String> m = machine();
        int q0 = m.getIntInitialState();
        assertEquals(-1, MealyMapping.pairStep(m, q0, "level_i", "o_low"));
        assertTrue(MealyMapping.contradicts(m, q0, "level_i", "o_low"), "the machine predicted o_high");
    }

    @Test
    void aQueryNeverSeenThereIsAGapNotAContradiction() {
        CompactMealy<String, String> m = machine();
        int q0 = m.getIntInitialState();
        assertEquals(-1, MealyMapping.pairStep(m, q0, "goTo_i", "o_goto"));
        assertFalse(MealyMapping.contradicts(m, q0, "goTo_i", "o_goto"), "no transition: the runs never did it");
        assertFalse(MealyMapping.contradicts(m, q0, "unknown_i", "o_x"), "not even in the alphabet");
        int q2 = MealyMapping.pairStep(m, q0, "level_i", "o_high");
        assertFalse(MealyMapping.contradicts(m, q2, "level_i", "o_high"), "nothing seen after the first pair");
    }
}
