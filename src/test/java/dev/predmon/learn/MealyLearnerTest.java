package dev.predmon.learn;

import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelStore;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.alphabet.Alphabets;
import net.automatalib.automaton.transducer.CompactMealy;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class MealyLearnerTest {

    private static final Alphabet<String> FIG_ALPHABET =
            Alphabets.fromList(List.of("Delta", "batteryStatus_i", "goTo_ki_i", "isAt_ki_i", "level_i"));

    /** Figure 4.10 learns into the 4-state machine of Figures 4.11/4.12, transition for transition. */
    @Test
    void figure410LearnsTheMachineOfFigure412() {
        CompactMealy<String, String> m = MealyLearner.learn(FIG_ALPHABET, List.of(ThesisExamples.figure410()));
        assertEquals(4, m.size());
        Integer hub = m.getInitialState(); // s3 in Figure 4.12
        assertEquals(hub, m.getSuccessor(hub, "level_i"));
        assertEquals("OK", m.getOutput(hub, "level_i"));
        assertEquals(hub, m.getSuccessor(hub, "Delta"));
        assertEquals("o_level_high", m.getOutput(hub, "Delta"));
        assertReturnsToHub(m, hub, "batteryStatus_i", "o_batteryStatus_false");
        assertReturnsToHub(m, hub, "isAt_ki_i", "o_isAt_ki_false");
        assertReturnsToHub(m, hub, "goTo_ki_i", "o_goto_ki");
    }

    private static void assertReturnsToHub(CompactMealy<String, String> m, Integer hub, String input, String answer) {
        Integer mid = m.getSuccessor(hub, input);
        assertEquals("OK", m.getOutput(hub, input));
        assertTrue(!mid.equals(hub), input + " leads to its own state");
        assertEquals(answer, m.getOutput(mid, "Delta"));
        assertEquals(hub, m.getSuccessor(mid, "Delta"));
        assertNull(m.getSuccessor(mid, "level_i"), "nothing but Delta was seen after " + input);
    }

    /** Example 2 (Section 4.1): the learned machine reproduces its samples. */
    @Test
    void example2SamplesAreReproduced() {
        MealyTrace s0 = ThesisExamples.chars("s0", "aabbba", "000111");
        MealyTrace s1 = ThesisExamples.chars("s1", "abbbbabb", "01101011");
        CompactMealy<String, String> m = MealyLearner.learn(Alphabets.fromList(List.of("a", "b")), List.of(s0, s1));
        assertEquals(s0.outputs(), m.computeOutput(s0.inputs()));
        assertEquals(s1.outputs(), m.computeOutput(s1.inputs()));
    }

    /** Example 1: abab answers 0000 and 0001; LearnLib alone would throw without a message. */
    @Test
    void example1ConflictIsNamedNotThrownByLearnLib() {
        MealyTrace x = ThesisExamples.chars("run-a.log", "abab", "0000");
        MealyTrace y = ThesisExamples.chars("run-b.log", "abab", "0001");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MealyLearner.learn(Alphabets.fromList(List.of("a", "b")), List.of(x, y)));
        assertTrue(e.getMessage().contains("run-a.log") && e.getMessage().contains("run-b.log"), e.getMessage());
        assertTrue(e.getMessage().contains("step 3"), e.getMessage());
    }

    @Test
    void sameSamplesGiveTheSameMachine() {
        List<MealyTrace> samples = List.of(ThesisExamples.chars("s0", "aabbba", "000111"),
                ThesisExamples.chars("s1", "abbbbabb", "01101011"));
        Alphabet<String> ab = Alphabets.fromList(List.of("a", "b"));
        String first = ModelStore.toDot(MealyLearner.learn(ab, samples), ab);
        String second = ModelStore.toDot(MealyLearner.learn(ab, samples), ab);
        assertEquals(first, second);
    }
}
