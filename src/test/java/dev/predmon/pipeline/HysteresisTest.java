package dev.predmon.pipeline;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
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

/** A noisy battery sensor hovering at a band boundary must not flip bands when the abstraction sets hysteresis. */
class HysteresisTest {

    private static Abstraction withHysteresis(Object value) throws Exception {
        ObjectMapper om = new ObjectMapper();
        ObjectNode root = (ObjectNode) om.readTree(Abstraction.class.getResourceAsStream("default-abstraction.json"));
        root.put("name", "noisy");
        for (var rule : root.get("rules")) {
            if (rule.get("command").asText().equals("level")) {
                ((ObjectNode) rule).set("hysteresis", om.valueToTree(value));
            }
        }
        return AbstractionFiles.fromJson("noisy.json", om.writeValueAsString(root));
    }

    private static final Records HOVERING = new Records().level(80).level(50.2).level(49.9).level(50.1).level(49.8)
            .level(49.4).level(45.2).level(44.9).level(45.3).level(44.2);

    private static List<String> bands(Abstraction a) {
        return Traces.compact(HOVERING.list(), a).stream().map(IoPair::output).toList();
    }

    @Test
    void withoutHysteresisEveryCrossingIsABand() {
        assertEquals(List.of("o_level_high", "o_level_medium_six", "o_level_high", "o_level_medium_six",
                "o_level_medium_five", "o_level_medium_six", "o_level_medium_five"), bands(AbstractionFiles.defaults()));
    }

    @Test
    void halfAPointOfHysteresisGivesOneCleanDescent() throws Exception {
        assertEquals(List.of("o_level_high", "o_level_medium_six", "o_level_medium_five"), bands(withHysteresis(0.5)));
    }

    @Test
    void hysteresisIsOnlyForContinuousRulesAndNeverNegative() {
        AbstractionException negative = assertThrows(AbstractionException.class, () -> withHysteresis(-1));
        assertTrue(negative.getMessage().contains("hysteresis"), negative.getMessage());
        String json = """
                {"name": "x", "rules": [{"protocol": "P", "command": "c", "input": "c_i", "hysteresis": 1,
                  "replies": [{"range": {"atMost": 0}, "symbol": "o_a"}, {"range": {"above": 0}, "symbol": "o_b"}]}]}""";
        AbstractionException notContinuous = assertThrows(AbstractionException.class, () -> AbstractionFiles.fromJson("x.json", json));
        assertTrue(notContinuous.getMessage().contains("continuous"), notContinuous.getMessage());
    }
}
