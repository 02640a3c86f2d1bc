package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * No verdict without evidence, as a user sees it: a property whose name no record holds reads "no evidence", never
 * "holds", at the end of watch, in its JSON and in explain; learn and {@code abstraction check} name each such name at
 * its key with the nearest names that occur, one line each; learn says how many training runs violated each property.
 */
class PropertyEvidenceCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path FIXTURES = Path.of("src/test/resources/property");
    /** scope-fetch with four typos: levle, ...Clinet, getStatsu, closehand (twice: the trigger and the counted). */
    private static final Path FOUR_TYPOS = FIXTURES.resolve("four-typos.json");

    @TempDir
    Path tmp;

    /** The thesis abstraction with its battery floor at 50, on a misspelt command. */
    private Path typoFloor() throws Exception {
        Cli show = Cli.run("abstraction", "show", "thesis");
        ObjectNode root = (ObjectNode) JSON.readTree(show.out());
        ObjectNode battery = (ObjectNode) root.get("properties").get(0);
        assertEquals("battery", battery.get("id").asText());
        ((ObjectNode) battery.get("value")).put("command", "levle");
        battery.put("floor", 50.0);
        battery.put("name", "battery level >= 50%");
        Path file = tmp.resolve("typo.json");
        Files.writeString(file, JSON.writeValueAsString(root));
        return file;
    }

    private Path handRuns() throws Exception {
        Path logs = tmp.resolve("logs");
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        return logs;
    }

    /** The property fixtures, and a run whose grasp succeeds (the last hasGrasped replies 1). */
    private Path fixtureLogs() throws Exception {
        Path logs = Files.createDirectories(tmp.resolve("recordings"));
        for (String f : List.of("grasp-fails.txt", "late-charger.txt", "navigation-aborts.txt", "navigation-stuck.txt")) {
            Files.copy(FIXTURES.resolve(f), logs.resolve(f));
        }
        String fails = Files.readString(FIXTURES.resolve("grasp-fails.txt"));
        int last = fails.lastIndexOf("Reply     : 0");
        Files.writeString(logs.resolve("grasp-succeeds.txt"), fails.substring(0, last) + "Reply     : 1"
                + fails.substring(last + "Reply     : 0".length()));
        return logs;
    }

    @Test
    void aFloorOfFiftyOnAMisspeltCommandNeverHoldsOnARunWhoseBatteryReachesZero() throws Exception {
        Path logs = handRuns();
        Path models = tmp.resolve("models");
        Cli learn = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString(), "--abstraction",
                typoFloor().toString());
        assertEquals(ExitCodes.OK, learn.code(), "a warning, not a refusal: " + learn.err());
        assertTrue(learn.err().contains("predmon: warning: " + tmp.resolve("typo.json")
                + ": properties[0].value.command (battery): 'levle' occurs in no log (nearest that occur: level)\n"),
                learn.err());
        assertTrue(learn.out().contains("battery: no evidence in any of the 2 training runs (nothing it speaks of "
                + "occurred): it cannot be forecast"), learn.out());

        Path depleted = logs.resolve("depleted/depleted-1.log");
        Cli watch = Cli.run("watch", "--no-follow", "--log", depleted.toString(), "--models", models.toString());
        assertTrue(watch.out().contains("battery (battery level >= 50%): no evidence (no reading of "
                + "BatteryReader/levle from /BatteryComponent to /BatteryReaderBatteryLevelClient in the run)"),
                watch.out());
        assertFalse(watch.out().contains("battery (battery level >= 50%): holds"), watch.out());

        Cli json = Cli.run("watch", "--no-follow", "--json", "--log", depleted.toString(), "--models",
                models.toString());
        JsonNode end = Cli.firstEvent(json.jsonLines(), "end").orElseThrow();
        JsonNode battery = end.get("properties").get(0);
        assertEquals("battery", battery.get("property").asText());
        assertEquals("no-evidence", battery.get("verdict").asText(), json.out());
        assertTrue(battery.get("what").asText().startsWith("no reading of BatteryReader/levle"), battery.toString());
    }

    @Test
    void learnSaysHowManyTrainingRunsViolatedEachProperty() throws Exception {
        Cli learn = Cli.run("learn", "--logs", handRuns().toString(), "--models", tmp.resolve("m").toString());
        assertEquals(ExitCodes.OK, learn.code(), learn.err());
        List<String> lines = learn.out().lines().toList();
        // the depleted run falls to 18 (below 20), the recharge run to 38; both navigate, neither aborts nor grasps
        assertTrue(lines.contains("battery: violated in 1 of 2 runs"), learn.out());
        assertTrue(lines.contains("no-abort: violated in 0 of 2 runs"), learn.out());
        assertTrue(lines.contains("grasp-in-time: no evidence in any of the 2 training runs (nothing it speaks of "
                + "occurred): it cannot be forecast, and reads \"no evidence\" on runs like them"), learn.out());
    }

    @Test
    void fourTyposGiveFourLinesEachAtItsKeyWithTheNearestNameThatOccurs() throws Exception {
        Path logs = fixtureLogs();
        Cli check = Cli.run("abstraction", "check", FOUR_TYPOS.toString(), logs.toString());
        assertEquals(ExitCodes.WARNING, check.code(), check.out() + check.err());
        String at = FOUR_TYPOS + ": ";
        assertEquals(List.of(
                at + "properties[0].value.command (battery): 'levle' occurs in no log (nearest that occur: level)",
                at + "properties[1].trigger.value.to (charger-in-time): '/BatteryReaderBatteryLevelClinet' occurs in no"
                        + " log (nearest that occur: /BatteryReaderBatteryLevelClient)",
                at + "properties[2].event.command (no-abort): 'getStatsu' occurs in no log (nearest that occur: "
                        + "getStatus)",
                at + "properties[4].trigger.command (grasp-in-time): 'closehand' occurs in no log (nearest that "
                        + "occur: closeHand)",
                "4 name(s) occur in none of the " + records(check) + " records of 5 log(s): the properties that hold "
                        + "them read \"no evidence\" on runs like these"), check.out().lines().toList());

        Cli right = Cli.run("abstraction", "check", "scope-fetch", logs.toString());
        assertEquals(ExitCodes.OK, right.code(), right.out());
        assertTrue(right.out().startsWith("every name of the 5 properties occurs in the "), right.out());
    }

    private static String records(Cli check) {
        String last = check.out().lines().reduce((a, b) -> b).orElseThrow();
        return last.replaceAll(".* none of the (\\d+) records.*", "$1");
    }

    @Test
    void learnWarnsOfEachTypoAndLearnsTheRest() throws Exception {
        Path models = tmp.resolve("models");
        Cli learn = Cli.run("learn", "--logs", fixtureLogs().toString(), "--models", models.toString(),
                "--abstraction", FOUR_TYPOS.toString());
        assertEquals(ExitCodes.OK, learn.code(), learn.err());
        List<String> warnings = learn.err().lines().filter(l -> l.startsWith("predmon: warning: " + FOUR_TYPOS))
                .toList();
        assertEquals(4, warnings.size(), learn.err());
        assertTrue(warnings.get(3).endsWith("properties[4].trigger.command (grasp-in-time): 'closehand' occurs in no "
                + "log (nearest that occur: closeHand)"), warnings.toString());
        assertTrue(Files.isRegularFile(models.resolve("index.json")), "the models are written");
        assertTrue(learn.out().lines().anyMatch(l -> l.startsWith("no-abort: no evidence in any of the 5 training "
                + "runs")), learn.out());
    }

    @Test
    void anAbstractionCheckOfNoLogIsBadInput() {
        Cli none = Cli.run("abstraction", "check", "scope-fetch", tmp.resolve("missing").toString());
        assertEquals(ExitCodes.BAD_INPUT, none.code());
        assertEquals("predmon: " + tmp.resolve("missing") + ": cannot read: no such file or folder\n", none.err());
    }

    @Test
    void explainSaysWhichPropertyHasNoEvidence() throws Exception {
        Path logs = handRuns();
        Path models = tmp.resolve("models");
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", logs.toString(), "--models", models.toString()).code());
        Cli explain = Cli.run("explain", "--log", logs.resolve("depleted/depleted-1.log").toString(), "--models",
                models.toString());
        assertTrue(explain.out().lines().anyMatch(l -> l.equals("grasp-in-time no evidence (no ArmService/closeHand "
                + "command (its trigger) in the run)")), explain.out());
        assertFalse(explain.out().contains("no-abort no evidence"), "getStatus replied, never 3: " + explain.out());
    }
}
