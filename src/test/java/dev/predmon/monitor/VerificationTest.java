package dev.predmon.monitor;

import dev.predmon.matching.ModelTracker;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.LearnedModel;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.alphabet.Alphabets;
import net.automatalib.automaton.transducer.CompactMealy;
import net.automatalib.word.Word;
import org.junit.jupiter.api.Test;

import java.util.Arrays;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

/** Algorithm 6's three cases on the machine of Figure 4.12, built by hand. */
class VerificationTest {

    private static final Alphabet<String> ALPHABET =
            Alphabets.fromList(List.of("Delta", "batteryStatus_i", "goTo_ki_i", "isAt_ki_i", "level_i"));

    /** Figure 4.12 (a): s3 is the hub; s0, s1, s2 answer goTo, batteryStatus, isAt. */
    private static LearnedModel figure412() {
        CompactMealy<String, String> m = new CompactMealy<>(ALPHABET);
        int s0 = m.addState(), s1 = m.addState(), s2 = m.addState(), s3 = m.addInitialState();
        m.addTransition(s0, "Delta", s3, "o_goto_ki");
        m.addTransition(s1, "Delta", s3, "o_batteryStatus_false");
        m.addTransition(s2, "Delta", s3, "o_isAt_ki_false");
        m.addTransition(s3, "Delta", s3, "o_level_high");
        m.addTransition(s3, "goTo_ki_i", s0, "OK");
        m.addTransition(s3, "level_i", s3, "OK");
        m.addTransition(s3, "batteryStatus_i", s1, "OK");
        m.addTransition(s3, "isAt_ki_i", s2, "OK");
        return new LearnedModel("fig412", "example", false, m, ALPHABET);
    }

    private static MealyTrace t(String in, String out) {
        return new MealyTrace(Word.fromList(Arrays.asList(in.split(" "))), Word.fromList(Arrays.asList(out.split(" "))), "t");
    }

    @Test
    void case1TheFigure410TraceMatches() {
        Verification v = Verification.of(figure412(), t(
                "level_i Delta batteryStatus_i Delta isAt_ki_i Delta goTo_ki_i Delta",
                "OK o_level_high OK o_batteryStatus_false OK o_isAt_ki_false OK o_goto_ki"));
        assertEquals(Verification.Verdict.MATCHES, v.verdict());
        assertEquals(8, v.steps());
        assertNull(v.failure());
    }

    @Test
    void case2OutputsDifferReportsFirstPositionAndBothSymbols() {
        Verification v = Verification.of(figure412(), t("level_i Delta isAt_ki_i Delta isAt_ki_i Delta",
                "OK o_level_medium OK o_isAt_ki_true OK o_isAt_ki_false"));
        assertEquals(Verification.Verdict.OUTPUTS_DIFFER, v.verdict());
        assertEquals(2, v.discrepancies());
        assertEquals(1, v.failure().step());
        assertEquals("o_level_high", v.failure().expected());
        assertEquals("o_level_medium", v.failure().seen());
        assertEquals(6, v.steps(), "the walk goes on after a differing output");
    }

    /** AutomataLib's computeOutput would silently return a shorter word here. */
    @Test
    void case3AnInputTheModelCannotTakeIsReportedNotTruncated() {
        Verification v = Verification.of(figure412(), t("goTo_ki_i goTo_ki_i Delta", "OK OK o_goto_ki"));
        assertEquals(Verification.Verdict.INPUT_UNDEFINED, v.verdict());
        assertEquals(1, v.failure().step());
        assertEquals("goTo_ki_i", v.failure().input());
    }

    @Test
    void aSymbolOutsideTheAlphabetIsAnUndefinedInputNotACrash() {
        Verification v = Verification.of(figure412(), t("teleport_i Delta", "OK o_x"));
        assertEquals(Verification.Verdict.INPUT_UNDEFINED, v.verdict());
        assertEquals(0, v.failure().step());
    }

    @Test
    void thresholdToleratesDiscrepanciesThenEliminates() {
        ModelTracker t = new ModelTracker(figure412(), 1);
        t.step("level_i", "OK");
        assertEquals(ModelTracker.Outcome.DISCREPANCY, t.step("Delta", "o_level_low"));
        assertEquals(true, t.alive());
        t.step("level_i", "OK");
        t.step("Delta", "o_level_low");
        assertEquals(false, t.alive());
        assertEquals(3, t.elimination().step());
    }
}
