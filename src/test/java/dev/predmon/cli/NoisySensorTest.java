package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A noisy battery sensor ({@code simulate --noise}): learn estimates the noise from the training runs and sets the
 * level rule's hysteresis, records it in index.json, and every command using the models applies it; noise-free
 * runs get none, so their models do not change.
 */
class NoisySensorTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    private Path runs(String name, String noise) {
        Path root = dir.resolve(name);
        for (String s : new String[] {"direct", "recharge", "depleted"}) {
            Cli r = Cli.run("simulate", "--scenario", s, "--seed", "61", "--runs", "4", "--noise", noise,
                    "--out-dir", root.resolve(s).toString());
            assertEquals(ExitCodes.OK, r.code(), r.err());
        }
        return root;
    }

    @Test
    void noiseZeroIsTheNoiseFreeSensorByteForByte() throws Exception {
        Path a = dir.resolve("a.log");
        Path b = dir.resolve("b.log");
        Path c = dir.resolve("c.log");
        assertEquals(ExitCodes.OK, Cli.run("simulate", "--scenario", "recharge", "--seed", "5", "--out", a.toString()).code());
        assertEquals(ExitCodes.OK, Cli.run("simulate", "--scenario", "recharge", "--seed", "5", "--noise", "0",
                "--out", b.toString()).code());
        assertEquals(ExitCodes.OK, Cli.run("simulate", "--scenario", "recharge", "--seed", "5", "--noise", "0.5",
                "--out", c.toString()).code());
        assertEquals(Files.readString(a), Files.readString(b));
        assertNotEquals(Files.readString(a), Files.readString(c));
        assertEquals(ExitCodes.USAGE, Cli.run("simulate", "--scenario", "recharge", "--noise", "-1").code());
    }

    @Test
    void learnEstimatesTheNoiseAndRecordsTheHysteresis() throws Exception {
        Path noisy = dir.resolve("m-noisy");
        Path clean = dir.resolve("m-clean");
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", runs("noisy", "0.5").toString(), "--models",
                noisy.toString()).code());
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", runs("clean", "0").toString(), "--models",
                clean.toString()).code());
        JsonNode h = JSON.readTree(noisy.resolve("index.json").toFile()).get("abstraction").get("hysteresis");
        assertTrue(h != null && h.get("level_i").asDouble() > 0, String.valueOf(h));
        assertFalse(JSON.readTree(clean.resolve("index.json").toFile()).get("abstraction").has("hysteresis"),
                "noise-free runs: no hysteresis, the index is as before");
        // The models learned with the hysteresis judge a noisy run with it: it matches its own scenario.
        Path log = dir.resolve("noisy/recharge/recharge-61.log");
        Cli v = Cli.run("verify", "--log", log.toString(), "--scenario", "recharge", "--models", noisy.toString());
        assertEquals(ExitCodes.OK, v.code(), v.out() + v.err());
    }
}
