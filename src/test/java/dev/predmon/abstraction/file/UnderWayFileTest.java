package dev.predmon.abstraction.file;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import dev.predmon.property.UnderWay;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The safety property's {@code underWay}: the messages that say its action is under way. Optional, validated, kept in
 * the canonical form, advice only (no fingerprint changes), and lent by a built-in to a copy without it.
 */
class UnderWayFileTest {

    private static final String RULES = "\"rules\": [{\"protocol\": \"B\", \"command\": \"level\", \"input\": \"level_i\","
            + " \"replies\": [{\"any\": true, \"symbol\": \"o_level\"}]}]";

    @TempDir
    Path dir;

    private static String file(String key) {
        return "{\"name\": \"mine\", " + RULES + ", \"safety\": {\"name\": \"level >= 20\", \"protocol\": \"B\","
                + " \"command\": \"level\", \"below\": 20" + key + "}}";
    }

    @Test
    void theMessagesAreReadKeptAndChangeNoFingerprint() throws Exception {
        Abstraction with = AbstractionFiles.fromJson("with.json", file(", \"underWay\": [{\"skill\": \"Dock\"},"
                + " {\"protocol\": \"GoTo\", \"command\": \"goTo\", \"argument\": \"dock\"}]"));
        Abstraction without = AbstractionFiles.fromJson("without.json", file(""));
        assertEquals(List.of(new UnderWay("Dock", null, null, null), new UnderWay(null, "GoTo", "goTo", "dock")),
                with.safety().orElseThrow().underWay());
        assertTrue(without.safety().orElseThrow().underWay().isEmpty());
        assertEquals(without.fingerprint(), with.fingerprint(), "advice changes no trace");
        Abstraction again = AbstractionFiles.fromJson("again.json", with.canonicalJson());
        assertEquals(with.canonicalJson(), again.canonicalJson());
    }

    @Test
    void theBuiltInsNameTheWayToTheChargerAndLendItToACopyWithoutIt() throws Exception {
        // models/abstraction.json of models learned before the advice and the properties list: the older form
        String stored = AbstractionFiles.defaults().canonicalJson()
                .replaceAll(",\"properties\":\\[.*\\](?=,\"rules\")", "");
        stored = stored.substring(0, stored.length() - 1) + ",\"safety\":{\"below\":20.0,\"command\":\"level\","
                + "\"from\":\"/BatteryComponent\",\"name\":\"battery level >= 20% (thesis 3.3.1)\","
                + "\"protocol\":\"BatteryReader\",\"to\":\"/BatteryReaderBatteryLevelClient\"}}";
        assertFalse(stored.contains("underWay"), stored);
        Abstraction old = AbstractionFiles.fromJson("models/abstraction.json", stored);
        assertEquals(AbstractionFiles.defaults().fingerprint(), old.fingerprint());
        assertEquals(List.of("goTo charging_station", "skill GoToChargingStation"),
                old.safety().orElseThrow().underWay().stream().map(UnderWay::describe).toList());
    }

    @Test
    void anEntryThatIsNeitherASkillNorACommandIsOneLineOfError() throws Exception {
        for (String bad : new String[] {"{}", "{\"skill\": \"Dock\", \"command\": \"goTo\"}",
            "{\"skill\": \"Dock\", \"argument\": \"dock\"}", "{\"argument\": \"dock\"}", "{\"skill\": \" \"}"}) {
            Path f = Files.writeString(dir.resolve("bad.json"), file(",\n \"underWay\": [" + bad + "]"));
            AbstractionException e = assertThrows(AbstractionException.class, () -> AbstractionFiles.load(f), bad);
            assertFalse(e.getMessage().contains("\n"), e.getMessage());
            assertTrue(e.getMessage().startsWith(f + ":2:"), e.getMessage());
            assertTrue(e.getMessage().contains("expected {\"skill\": NAME}"), e.getMessage());
        }
    }
}
