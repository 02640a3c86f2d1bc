package dev.predmon.abstraction.file;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The safety property's recommended {@code action}: optional, validated, kept in the canonical form, and advice only,
 * so that it changes no fingerprint and models learned before it stay valid.
 */
class SafetyActionTest {

    private static final String RULES = "\"rules\": [{\"protocol\": \"B\", \"command\": \"level\", \"input\": \"level_i\","
            + " \"replies\": [{\"any\": true, \"symbol\": \"o_level\"}]}]";

    @TempDir
    Path dir;

    private static String file(String actionKey) {
        return "{\"name\": \"mine\", " + RULES + ", \"safety\": {\"name\": \"level >= 20\", \"protocol\": \"B\","
                + " \"command\": \"level\", \"below\": 20" + actionKey + "}}";
    }

    @Test
    void theActionIsReadKeptAndChangesNoFingerprint() throws Exception {
        Abstraction with = AbstractionFiles.fromJson("with.json", file(", \"action\": \"plug the robot in\""));
        Abstraction without = AbstractionFiles.fromJson("without.json", file(""));
        assertEquals("plug the robot in", with.safety().orElseThrow().action());
        assertNull(without.safety().orElseThrow().action(), "no action given, and no built-in is this file");
        assertTrue(with.canonicalJson().contains("\"action\":\"plug the robot in\""), with.canonicalJson());
        assertEquals(without.fingerprint(), with.fingerprint(), "advice changes no trace");
        Abstraction again = AbstractionFiles.fromJson("again.json", with.canonicalJson());
        assertEquals(with.canonicalJson(), again.canonicalJson(), "the canonical form reads back to itself");
        assertEquals("plug the robot in", again.safety().orElseThrow().action());
    }

    @Test
    void theBuiltInsRecommendChargingAndLendItToACopyWithoutAnAction() throws Exception {
        for (String name : List.of("thesis", "scope-fetch")) { // the R1 system's built-ins
            assertEquals("send the robot to the charging station",
                    AbstractionFiles.builtin(name).orElseThrow().safety().orElseThrow().action(), name);
        }
        // models/abstraction.json of models learned before actions and properties existed: the built-in in the
        // older form, one safety object without an action. It gets the built-in's properties and their actions.
        String stored = AbstractionFiles.defaults().canonicalJson().replaceAll(",\"properties\":\\[.*\\](?=,\"rules\")",
                "") + "";
        stored = stored.substring(0, stored.length() - 1) + ",\"safety\":{\"below\":20.0,\"command\":\"level\","
                + "\"from\":\"/BatteryComponent\",\"name\":\"battery level >= 20% (thesis 3.3.1)\","
                + "\"protocol\":\"BatteryReader\",\"to\":\"/BatteryReaderBatteryLevelClient\"}}";
        assertFalse(stored.contains("action"), stored);
        Abstraction old = AbstractionFiles.fromJson("models/abstraction.json", stored);
        assertEquals(AbstractionFiles.defaults().fingerprint(), old.fingerprint());
        assertEquals("send the robot to the charging station", old.safety().orElseThrow().action());
        assertEquals(AbstractionFiles.defaults().properties(), old.properties());
    }

    @Test
    void aBlankOrMultiLineActionIsOneLineOfError() throws Exception {
        for (String bad : new String[] {"\"\"", "\"  \"", "\"first\\nsecond\"", "\"" + "x".repeat(121) + "\""}) {
            Path f = Files.writeString(dir.resolve("bad.json"), file(",\n \"action\": " + bad));
            AbstractionException e = assertThrows(AbstractionException.class, () -> AbstractionFiles.load(f), bad);
            assertFalse(e.getMessage().contains("\n"), e.getMessage());
            assertTrue(e.getMessage().startsWith(f + ":2:"), e.getMessage());
            assertTrue(e.getMessage().contains("safety.action"), e.getMessage());
        }
    }
}
