package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.compact.IoPair;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A carried query's Mealy input names its previous answer, identically for learn and watch (one pipeline). */
class CarryTest {

    private static final Abstraction A = AbstractionFiles.defaults();

    @Test
    void levelQueriesCarryTheirPreviousBandOtherQueriesDoNot() {
        List<IoPair> pairs = Traces.compact(new Records().level(80).isAt("kitchen", false).level(47)
                .isAt("kitchen", true).level(42).list(), A);
        assertEquals(List.of("level_i", "isAt_ki_i", "level_i_after_o_level_high", "isAt_ki_i",
                "level_i_after_o_level_medium_six"), pairs.stream().map(IoPair::input).toList());
        assertEquals(List.of("o_level_high", "o_isAt_ki_false", "o_level_medium_six", "o_isAt_ki_true",
                "o_level_medium_five"), pairs.stream().map(IoPair::output).toList());
    }

    /** Bands crossed between two readings carry the band just left, one after the other. */
    @Test
    void expandedBandsCarryEachOther() {
        List<IoPair> pairs = Traces.compact(new Records().level(80).level(41).list(), A);
        assertEquals(List.of("level_i", "level_i_after_o_level_high", "level_i_after_o_level_medium_six"),
                pairs.stream().map(IoPair::input).toList());
    }

    @Test
    void everyCarriedInputIsInTheModelAlphabet() {
        List<String> alphabet = List.copyOf(MealyAlphabet.inputs(A));
        for (String band : A.outputAlphabet().stream().filter(s -> s.startsWith("o_level_")).toList()) {
            assertTrue(alphabet.contains("level_i_after_" + band), band);
        }
        assertTrue(alphabet.contains("level_i") && alphabet.contains("Delta") && alphabet.contains("goTo_ki_i"));
        assertTrue(alphabet.stream().noneMatch(s -> s.contains("isAt_ki_i_after")), "only carried rules");
    }

    @Test
    void carryCanOnlyBeTrue() {
        String json = """
                {"name": "x", "rules": [{"protocol": "P", "command": "c", "input": "c_i", "carry": false,
                  "replies": [{"equals": ["1"], "symbol": "o_one"}]}]}""";
        AbstractionException e = assertThrows(AbstractionException.class, () -> AbstractionFiles.fromJson("x.json", json));
        assertTrue(e.getMessage().contains("carry"), e.getMessage());
    }
}
