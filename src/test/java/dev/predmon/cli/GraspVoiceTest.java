package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * One voice: on a run whose grasp is retried past its limit, while the battery stays far above its floor, every
 * output names grasp-in-time as violated, first, and the battery as holding. A console capture written by hand
 * (eleven closeHand attempts, none grasped; the limit is eight) and a run {@code simulate --grasp-failures} makes.
 */
class GraspVoiceTest {

    /** Eleven closeHand attempts from line 234 on, each answered by hasGrasped 0; the ninth, at line 634, is one too many. */
    static final Path FIXTURE = Path.of("src/test/resources/voice/grasp-retried.txt");
    private static final Path MODELS = Path.of("models");
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String OTHERS_HOLD = "battery, charger-in-time, no-abort, navigation-in-time hold";

    @TempDir
    Path dir;

    /** A run of the direct scenario whose grasp fails 12 times: the ninth attempt violates grasp-in-time. */
    static Path simulated(Path dir) {
        Path log = dir.resolve("grasp.log");
        Cli r = Cli.run("simulate", "--scenario", "direct", "--seed", "3", "--grasp-failures", "12", "--out",
                log.toString());
        assertEquals(0, r.code(), r.err());
        return log;
    }

    private static JsonNode endEvent(String out) throws Exception {
        List<String> lines = out.lines().toList();
        JsonNode end = JSON.readTree(lines.get(lines.size() - 1));
        assertEquals("end", end.get("event").asText(), out);
        return end;
    }

    @Test
    void watchsEndLineAndJsonLeadWithGraspInTimeViolatedAndTheBatteryHolding() throws Exception {
        Cli text = Cli.run("watch", "--log", FIXTURE.toString(), "--models", MODELS.toString(), "--no-follow");
        assertEquals(ExitCodes.UNWARNED_VIOLATION, text.code(), text.err());
        // the violation as an operator says it, not the matcher's description
        assertTrue(text.out().contains("line 634: VIOLATION of 'a grasp succeeds within 8 attempts' (grasp-in-time): "
                + "8 closeHand attempts since line 234, none answered by hasGrasped 1 or 27503\n"), text.out());
        String end = text.out().lines().filter(l -> l.startsWith("end of ")).findFirst().orElseThrow();
        assertTrue(end.endsWith("; grasp-in-time VIOLATED with no warning before it; " + OTHERS_HOLD
                + "; no model matches the run"), end);
        assertFalse(text.out().contains("property held"), text.out());
        // each property's line, worst first
        List<String> lines = text.out().lines().toList();
        int at = lines.indexOf(end);
        assertTrue(lines.get(at + 1).startsWith("  grasp-in-time (a grasp succeeds within 8 attempts): violated at "
                + "line 634"), lines.get(at + 1));
        assertTrue(lines.get(at + 2).startsWith("  battery (battery level >= 20% (thesis 3.3.1)): holds"),
                lines.get(at + 2));
        assertTrue(text.out().contains("\nlast forecast of battery: "), "the forecast is the battery's: " + text.out());

        Cli json = Cli.run("watch", "--log", FIXTURE.toString(), "--models", MODELS.toString(), "--no-follow",
                "--json");
        JsonNode outcome = endEvent(json.out()).get("outcome");
        assertEquals("grasp-in-time", outcome.get("worst").asText(), outcome.toString());
        assertEquals("violated", outcome.get("state").asText());
        assertEquals("[\"grasp-in-time\"]", outcome.get("violated").toString());
        assertEquals("[]", outcome.get("warned").toString());
        assertEquals("battery", outcome.get("properties").get(1).get("property").asText());
        assertEquals("holds", outcome.get("properties").get(1).get("state").asText());
        assertEquals(634, outcome.get("properties").get(0).get("line").asLong());
        // the deprecated aliases still say what they said: the battery, the forecast's property, was not violated
        assertFalse(endEvent(json.out()).get("violation").asBoolean());
        assertEquals(outcome, endEvent(json.out()).get("runs").get(0).get("outcome"));
    }

    @Test
    void explainAndClassifyNameGraspInTimeViolatedFirst() throws Exception {
        Cli x = Cli.run("explain", "--log", FIXTURE.toString(), "--models", MODELS.toString());
        assertEquals(ExitCodes.UNWARNED_VIOLATION, x.code(), x.err());
        assertTrue(x.out().contains("\ngrasp-in-time VIOLATED at line 634 with no warning before it: 8 closeHand "
                + "attempts since line 234, none answered by hasGrasped 1 or 27503\n" + OTHERS_HOLD
                + " throughout the log\n"), x.out());
        assertTrue(x.out().contains("watch does not warn of any property"), x.out());
        assertFalse(x.out().contains("the safety property holds"), x.out());
        JsonNode xj = JSON.readTree(Cli.run("explain", "--log", FIXTURE.toString(), "--models", MODELS.toString(),
                "--json").out());
        assertEquals("grasp-in-time", xj.get("outcome").get("worst").asText(), xj.get("outcome").toString());

        Cli c = Cli.run("classify", "--log", FIXTURE.toString(), "--models", MODELS.toString());
        assertEquals(ExitCodes.UNWARNED_VIOLATION, c.code(), c.err());
        assertTrue(c.out().contains("watch's verdict at the end of the log: grasp-in-time VIOLATED with no warning "
                + "before it; " + OTHERS_HOLD + " (exit 6)"), c.out());
        assertFalse(c.out().contains("a warning was raised"), c.out());
        JsonNode cj = JSON.readTree(Cli.run("classify", "--log", FIXTURE.toString(), "--models", MODELS.toString(),
                "--json").out());
        assertEquals("[\"grasp-in-time\"]", cj.get("outcome").get("violated").toString(), cj.toString());
    }

    @Test
    void theShippedHookSendsTheViolatedPropertyWithItsWords() throws Exception {
        // the shipped configuration's command, writing to a file instead of the robot's port
        String shipped = Files.readAllLines(Path.of("docs/predmon-watch.conf")).stream()
                .filter(l -> l.startsWith("on-violation = ")).findFirst().orElseThrow()
                .substring("on-violation = ".length());
        assertTrue(shipped.contains("$PREDMON_PROPERTY"), shipped);
        Path sent = dir.resolve("sent.txt");
        Path env = dir.resolve("env.txt");
        String command = shipped.replace("| yarp write ... /robot/predmon:i", ">> '" + sent + "'")
                + "; env | grep '^PREDMON_' >> '" + env + "'";
        Cli r = Cli.run("watch", "--log", FIXTURE.toString(), "--models", MODELS.toString(), "--no-follow",
                "--on-violation", command);
        assertEquals(ExitCodes.UNWARNED_VIOLATION, r.code(), r.err());
        assertEquals(List.of("violation grasp-in-time 634"), Files.readAllLines(sent));
        List<String> vars = Files.readAllLines(env);
        assertTrue(vars.contains("PREDMON_PROPERTY_NAME=a grasp succeeds within 8 attempts"), vars.toString());
        assertTrue(vars.contains("PREDMON_WHAT=8 closeHand attempts since line 234, none answered by hasGrasped 1 or "
                + "27503"), vars.toString());
        assertTrue(vars.contains("PREDMON_ACTION=check the object and the hand"), vars.toString());
        String readme = Files.readString(Path.of("README.md"));
        assertTrue(readme.contains("--on-warning 'echo \"warning $PREDMON_PROPERTY "), "the README's hook names it");
    }

    @Test
    void aSimulatedGraspRetriedPastItsLimitReadsTheSame() throws Exception {
        Path log = simulated(dir);
        JsonNode truth = JSON.readTree(dir.resolve("grasp.log.truth.json").toFile()).get("properties");
        assertTrue(truth.get("grasp-in-time").get("violated").asBoolean(), truth.toString());
        assertFalse(truth.get("battery").get("violated").asBoolean(), truth.toString());

        Cli w = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow");
        assertEquals(ExitCodes.UNWARNED_VIOLATION, w.code(), w.err());
        String end = w.out().lines().filter(l -> l.startsWith("end of ")).findFirst().orElseThrow();
        assertTrue(end.endsWith("; grasp-in-time VIOLATED with no warning before it; " + OTHERS_HOLD), end);
        assertTrue(w.out().contains("8 closeHand attempts since line "), w.out());

        Cli x = Cli.run("explain", "--log", log.toString(), "--models", MODELS.toString());
        assertEquals(ExitCodes.UNWARNED_VIOLATION, x.code(), x.err());
        assertTrue(x.out().contains("\ngrasp-in-time VIOLATED at line ") && x.out().contains(OTHERS_HOLD
                + " throughout the log\n"), x.out());
        assertFalse(x.out().contains("the safety property holds"), x.out());
        Cli c = Cli.run("classify", "--log", log.toString(), "--models", MODELS.toString());
        assertEquals(ExitCodes.UNWARNED_VIOLATION, c.code(), c.err());
        assertFalse(c.out().contains("a warning was raised"), c.out());
        assertTrue(c.out().contains("watch's verdict at the end of the log: grasp-in-time VIOLATED with no warning "
                + "before it; " + OTHERS_HOLD + " (exit 6)"), c.out());
    }
}
