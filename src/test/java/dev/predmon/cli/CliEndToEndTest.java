package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.support.HandRuns;
import dev.predmon.support.Records;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** learn, verify, classify and watch through the command line, on hand-written logs of two scenarios. */
class CliEndToEndTest {

    @TempDir
    Path tmp;
    Path logs;
    Path models;

    /**
     * Learns the hand-written recharge (nominal, named {@code nominal}) and depleted (faulty) runs from
     * {@code logs} into {@code models}, as most CLI tests need before they judge a log.
     */
    static void learnHandRuns(Path logs, Path models, String nominal) throws Exception {
        scenario(logs, nominal, false, HandRuns.recharge().text());
        scenario(logs, "depleted", true, HandRuns.depleted().text());
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", logs.toString(), "--models", models.toString()).code());
    }

    static void scenario(Path logs, String name, boolean faulty, String... texts) throws Exception {
        Path dir = Files.createDirectories(logs.resolve(name));
        Files.writeString(dir.resolve("scenario.json"), "{\"faulty\": " + faulty + ", \"description\": \"" + name + "\"}");
        for (int i = 0; i < texts.length; i++) {
            Files.writeString(dir.resolve(name + "-" + (i + 1) + ".log"), texts[i]);
        }
    }

    @BeforeEach
    void learn() throws Exception {
        logs = tmp.resolve("logs");
        models = tmp.resolve("models");
        scenario(logs, "recharge", false, HandRuns.recharge().text());
        scenario(logs, "depleted", true, HandRuns.depleted().text());
        Cli r = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("scenario recharge (nominal)"), r.out());
        assertTrue(Files.isRegularFile(models.resolve("depleted.dot")));
        assertTrue(Files.isRegularFile(models.resolve("index.json")));
    }

    @Test
    void watchJsonOnAFaultyLogWarnsBeforeTheViolation() throws Exception {
        Path log = Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text());
        Cli r = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow", "--json");
        assertEquals(ExitCodes.WARNING, r.code(), r.err());
        List<JsonNode> events = new ArrayList<>();
        for (String line : r.out().split("\n", 0)) {
            events.add(new ObjectMapper().readTree(line));
        }
        JsonNode warning = events.stream().filter(e -> e.get("event").asText().equals("warning")).findFirst().orElseThrow();
        JsonNode violation = events.stream().filter(e -> e.get("event").asText().equals("violation")).findFirst().orElseThrow();
        assertEquals("depleted", warning.get("scenario").asText());
        assertTrue(warning.get("time").asDouble() < violation.get("time").asDouble());
        assertTrue(warning.get("value").asDouble() > 20.0);
        assertEquals(18.0, violation.get("value").asDouble(), 1e-9);
        // the older name, kept for existing scripts
        assertEquals(warning.get("value"), warning.get("battery"));
        assertEquals(violation.get("value"), violation.get("battery"));
        assertEquals("end", events.get(events.size() - 1).get("event").asText());
    }

    @Test
    void watchOnANominalLogPrintsNoWarning() throws Exception {
        Path log = Files.writeString(tmp.resolve("run.log"), HandRuns.recharge().text());
        Cli r = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow", "--json");
        assertEquals(ExitCodes.OK, r.code(), r.err());
        assertTrue(!r.out().contains("\"warning\"") || r.out().contains("\"warning\":false"), r.out());
    }

    @Test
    void verifyReportsWhetherEachMachineMatches() throws Exception {
        Path log = Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text());
        Cli ok = Cli.run("verify", "--log", log.toString(), "--scenario", "depleted", "--models", models.toString());
        assertEquals(0, ok.code(), ok.err());
        assertTrue(ok.out().contains("depleted: matches ("), ok.out());
        Cli bad = Cli.run("verify", "--log", log.toString(), "--scenario", "recharge", "--models", models.toString());
        assertEquals(1, bad.code());
        assertTrue(bad.out().contains("recharge: eliminated: "), bad.out());
    }

    @Test
    void classifyNamesTheFaultyBestMatch() throws Exception {
        Path log = Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text());
        Cli r = Cli.run("classify", "--log", log.toString(), "--models", models.toString(), "--json");
        assertEquals(ExitCodes.WARNING, r.code(), r.err());
        JsonNode o = new ObjectMapper().readTree(r.out());
        assertEquals("depleted", o.get("scenario").asText());
        assertTrue(o.get("faulty").asBoolean());
    }

    @Test
    void missingModelsIsOneLineAndExit3() {
        Cli r = Cli.run("watch", "--log", "x.log", "--models", tmp.resolve("none").toString(), "--no-follow");
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains("none"), r.err());
    }

    @Test
    void aScenarioWithoutScenarioJsonIsNamed() throws Exception {
        Files.createDirectories(logs.resolve("orphan"));
        Files.writeString(logs.resolve("orphan/a.log"), new Records().level(50).text());
        Cli r = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertTrue(r.err().contains("orphan") && r.err().contains("scenario.json"), r.err());
        assertTrue(Files.isRegularFile(models.resolve("depleted.dot")), "the previous models are intact");
    }

    @Test
    void usageErrorIsExit2() {
        assertEquals(ExitCodes.USAGE, Cli.run("watch").code());
    }

    @Test
    void aNegativeThresholdIsAUsageErrorForEveryMatchingCommand() {
        for (String command : List.of("watch", "classify", "explain")) {
            Cli r = Cli.run(command, "--log", "x.log", "--tolerance", "-1");
            assertEquals(ExitCodes.USAGE, r.code(), command);
            assertTrue(r.err().contains("--tolerance must be at least 0"), r.err());
        }
        assertEquals(ExitCodes.USAGE, Cli.run("evaluate", "--logs", "x", "--tolerance", "-2").code());
    }
}
