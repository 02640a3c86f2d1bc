package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.compact.IoPair;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The battery level is continuous: a robot that reads it rarely must give the same compacted trace as one that
 * reads it often, so a jump across bands is a pass through each of them.
 */
class ContinuousBandsTest {

    private static final Abstraction A = AbstractionFiles.defaults();

    private static List<String> levels(List<IoPair> pairs) {
        return pairs.stream().filter(p -> p.input().startsWith("level_i")).map(IoPair::output).toList();
    }

    @Test
    void aJumpDownCrossesEveryBandInOrder() {
        assertEquals(List.of("o_level_medium_six", "o_level_medium_five"), A.bandPath("o_level_high", "o_level_medium_five"));
    }

    @Test
    void chargingUpCrossesEveryBandInOrder() {
        assertEquals(List.of("o_level_medium_three", "o_level_medium_four", "o_level_medium_five", "o_level_medium_six",
                "o_level_high"), A.bandPath("o_level_medium_two", "o_level_high"));
    }

    @Test
    void neighboursFirstAnswersAndOtherQueriesAreUnchanged() {
        assertEquals(List.of("o_level_medium_five"), A.bandPath("o_level_medium_six", "o_level_medium_five"));
        assertEquals(List.of("o_level_medium_five"), A.bandPath(null, "o_level_medium_five"));
        assertEquals(List.of("o_isAt_ki_true"), A.bandPath("o_isAt_ki_false", "o_isAt_ki_true"));
    }

    @Test
    void slowAndFastPollingGiveTheSameTrace() {
        Records fast = new Records();
        for (double level = 80; level >= 19; level -= 0.5) {
            fast.level(level);
        }
        Records slow = new Records().level(80).level(52).level(41).level(29).level(19);
        List<IoPair> f = Traces.compact(fast.list(), A);
        List<IoPair> s = Traces.compact(slow.list(), A);
        assertEquals(levels(f), levels(s));
        assertEquals(List.of("o_level_high", "o_level_medium_six", "o_level_medium_five", "o_level_medium_four",
                "o_level_medium_three", "o_level_medium_two", "o_level_medium_one", "o_level_low"), levels(s));
    }

    @Test
    void continuousNeedsRangesOnly() {
        String json = """
                {"name": "x", "rules": [{"protocol": "P", "command": "c", "input": "c_i", "continuous": true,
                  "replies": [{"equals": ["1"], "symbol": "o_one"}]}]}""";
        AbstractionException e = assertThrows(AbstractionException.class, () -> AbstractionFiles.fromJson("x.json", json));
        assertTrue(e.getMessage().contains("continuous"), e.getMessage());
    }
}
