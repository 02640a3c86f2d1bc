package dev.predmon.matching;

import dev.predmon.compact.IoPair;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.model.LearnedModel;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.alphabet.Alphabets;
import net.automatalib.automaton.transducer.CompactMealy;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The two ways every nominal machine can be eliminated: by a reply other than the one it predicted (a
 * contradiction: the run is unlike the safe runs where they were sure) or at a query it has no transition for (a gap:
 * no safe run did that there, the run is only new). The thesis's rule warns on both; the forecast rule takes only the
 * first.
 */
class MatchingTest {

    private static final Alphabet<String> ALPHABET = Alphabets.fromList(List.of("goTo_i", "level_i",
            MealyMapping.DELTA));

    /** A nominal machine whose runs read the level once and were answered o_high; nothing else. */
    private static LearnedModel nominal() {
        CompactMealy<String, String> m = new CompactMealy<>(ALPHABET);
        int q0 = m.addInitialState();
        int q1 = m.addState();
        int q2 = m.addState();
        m.addTransition(q0, "level_i", q1, MealyMapping.OK);
        m.addTransition(q1, MealyMapping.DELTA, q2, "o_high");
        return new LearnedModel("safe", "safe", false, m, ALPHABET);
    }

    /** A faulty machine whose runs read the level and were answered o_low, or went somewhere, in any order. */
    private static LearnedModel faulty() {
        CompactMealy<String, String> m = new CompactMealy<>(ALPHABET);
        int q0 = m.addInitialState();
        int read = m.addState();
        int went = m.addState();
        m.addTransition(q0, "level_i", read, MealyMapping.OK);
        m.addTransition(read, MealyMapping.DELTA, q0, "o_low");
        m.addTransition(q0, "goTo_i", went, MealyMapping.OK);
        m.addTransition(went, MealyMapping.DELTA, q0, "o_goto");
        return new LearnedModel("bad", "bad", true, m, ALPHABET);
    }

    private static Matching.Step first(String input, String output) {
        Matching matching = new Matching(List.of(nominal(), faulty()), 0, 0);
        return matching.pair(new IoPair(input, output, null, null));
    }

    @Test
    void aPairTheNominalMachineTakesLeavesItAlive() {
        Matching.Step step = first("level_i", "o_high");
        assertTrue(step.nominalAlive());
        assertFalse(step.ruleWarns());
        assertFalse(step.contradicted());
        assertEquals(List.of("bad"), step.eliminated().stream().map(t -> t.model().id()).toList());
    }

    @Test
    void anotherReplyThanTheOnePredictedIsAContradiction() {
        Matching.Step step = first("level_i", "o_low");
        assertFalse(step.nominalAlive());
        assertEquals(List.of("bad"), step.faultyAlive());
        assertTrue(step.ruleWarns(), "the thesis's rule: only a faulty machine matches");
        assertTrue(step.contradicted(), "the nominal machine predicted o_high");
        assertEquals("o_high", step.eliminated().get(0).elimination().expected());
    }

    @Test
    void aQueryNoSafeRunMadeThereIsAGapNotAContradiction() {
        Matching.Step step = first("goTo_i", "o_goto");
        assertFalse(step.nominalAlive());
        assertTrue(step.ruleWarns(), "the thesis's rule warns all the same");
        assertFalse(step.contradicted(), "no transition: the safe runs never did it");
    }

    @Test
    void everyNominalMachineMustBeContradicted() {
        CompactMealy<String, String> m = new CompactMealy<>(ALPHABET); // safe runs that only ever went somewhere
        int q0 = m.addInitialState();
        int q1 = m.addState();
        m.addTransition(q0, "goTo_i", q1, MealyMapping.OK);
        m.addTransition(q1, MealyMapping.DELTA, q0, "o_goto");
        LearnedModel walker = new LearnedModel("safe-2", "safe", false, m, ALPHABET);
        Matching matching = new Matching(List.of(nominal(), walker, faulty()), 0, 0);
        Matching.Step step = matching.pair(new IoPair("level_i", "o_low", null, null));
        assertFalse(step.nominalAlive());
        assertFalse(step.contradicted(), "one nominal machine predicted o_high, the other never read the level");
    }

    /**
     * The faulty scenario a warning names when no faulty machine matches any more: the one that matched longest, here
     * "bad", which took the level reading and was eliminated at the query after; "early" was out at the first pair.
     */
    @Test
    void theLikeliestFaultyScenarioIsTheOneStillMatchingElseTheLastEliminated() {
        CompactMealy<String, String> m = new CompactMealy<>(ALPHABET);
        m.addInitialState();
        LearnedModel early = new LearnedModel("early", "early", true, m, ALPHABET);
        Matching matching = new Matching(List.of(nominal(), early, faulty()), 0, 0);
        Matching.Step step = matching.pair(new IoPair("level_i", "o_low", null, null));
        assertEquals(List.of("bad"), step.faultyAlive());
        assertEquals("bad", matching.likeliestFaulty(step.faultyAlive()));
        step = matching.pair(new IoPair("level_i", "o_nothing_learned", null, null));
        assertEquals(List.of(), step.faultyAlive(), "every faulty machine is out");
        assertEquals("bad", matching.likeliestFaulty(step.faultyAlive()));
        assertEquals(null, new Matching(List.of(nominal()), 0, 0).likeliestFaulty(List.of()), "no faulty machine");
    }
}
