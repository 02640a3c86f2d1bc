package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.simulate.Day;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A robot's day: several runs one after another in one log (the tick counter starts again with each). Each run is
 * matched from the models' initial states and gets its own warning, violation and lead, in watch (after the fact and
 * live), evaluate and learn alike.
 */
class SeveralRunsTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final SimOptions O = SimOptions.defaults();

    @TempDir
    Path dir;

    /** The shipped sample logs' models are learned from single-run logs. */
    private static final Path MODELS = Path.of("models");

    private Path day(String name, long seed, Scenario... scenarios) throws Exception {
        Path log = dir.resolve(name);
        StringBuilder text = new StringBuilder();
        for (SimRun run : Day.simulate(List.of(scenarios), seed, scenarios.length, O)) {
            text.append(LogWriter.toText(run, O));
        }
        Files.writeString(log, text);
        return log;
    }

    private static List<JsonNode> events(String out) throws Exception {
        return new Cli(0, out, "").jsonLines();
    }

    @Test
    void aFaultyRunAfterANominalOneIsWarnedInItsOwnRun() throws Exception {
        Path log = day("day.log", 11, Scenario.DIRECT, Scenario.DEPLETED, Scenario.RECHARGE);
        Cli w = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow", "--json");
        assertEquals(ExitCodes.WARNING, w.code(), w.err());
        List<JsonNode> events = events(w.out());
        JsonNode warning = events.stream().filter(e -> e.get("event").asText().equals("warning")).findFirst().orElseThrow();
        JsonNode violation = events.stream().filter(e -> e.get("event").asText().equals("violation")).findFirst().orElseThrow();
        assertEquals(1, warning.get("run").asInt());
        assertEquals(1, violation.get("run").asInt());
        assertEquals(2, events.stream().filter(e -> e.get("event").asText().equals("run")).count(), "runs 1 and 2 begin");
        JsonNode end = events.get(events.size() - 1);
        JsonNode runs = end.get("runs");
        assertEquals(3, runs.size());
        assertFalse(runs.get(0).get("warning").asBoolean());
        assertTrue(runs.get(1).get("warning").asBoolean() && runs.get(1).get("violation").asBoolean());
        assertTrue(runs.get(1).get("lead").asDouble() > 0);
        assertFalse(runs.get(2).get("warning").asBoolean() || runs.get(2).get("violation").asBoolean());
        assertFalse(runs.get(2).get("noMatch").asBoolean() && runs.get(0).get("noMatch").asBoolean());
    }

    @Test
    void classifyAndVerifyJudgeEachRun() throws Exception {
        Path log = day("cv.log", 11, Scenario.DIRECT, Scenario.DEPLETED);
        Cli c = Cli.run("classify", "--log", log.toString(), "--models", MODELS.toString(), "--json");
        assertEquals(ExitCodes.WARNING, c.code(), "the depleted run is faulty: " + c.out());
        JsonNode runs = JSON.readTree(c.out()).get("runs");
        assertEquals(2, runs.size());
        assertFalse(runs.get(0).get("faulty").asBoolean());
        assertTrue(runs.get(1).get("faulty").asBoolean());
        assertTrue(runs.get(1).get("log").asText().endsWith("cv.log#1"));
        Cli v = Cli.run("verify", "--log", log.toString(), "--scenario", "direct", "--models", MODELS.toString());
        assertEquals(ExitCodes.WARNING, v.code(), "run 1 is no direct run: " + v.out());
        assertTrue(v.out().contains("cv.log#0: ") && v.out().contains("cv.log#1: "), v.out());
    }

    @Test
    void aRunCutShortIsStillARun() throws Exception {
        Path full = day("full.log", 21, Scenario.RECHARGE, Scenario.DEPLETED);
        String text = Files.readString(full);
        Path cut = dir.resolve("cut.log");
        Files.writeString(cut, text.substring(0, text.length() * 3 / 4)); // inside the depleted run, mid-record
        Cli w = Cli.run("watch", "--log", cut.toString(), "--models", MODELS.toString(), "--no-follow", "--json");
        List<JsonNode> events = events(w.out());
        JsonNode end = events.get(events.size() - 1);
        assertEquals(2, end.get("runs").size(), w.out());
        assertFalse(end.get("runs").get(0).get("warning").asBoolean(), "the nominal run stays quiet");
    }

    @Test
    void evaluateScoresEachRunAndLearnTakesOneSamplePerRun() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("days"));
        Files.move(day("a.log", 31, Scenario.DIRECT, Scenario.DEPLETED), folder.resolve("a.log"));
        Files.move(day("b.log", 41, Scenario.RECHARGE, Scenario.DEPLETED), folder.resolve("b.log"));
        Cli e = Cli.run("evaluate", "--logs", "sample-logs", "--test", folder.toString(), "--json", "--quiet");
        assertEquals(ExitCodes.OK, e.code(), e.err());
        JsonNode runs = JSON.readTree(e.out()).get("runs");
        assertEquals(4, runs.size(), "two runs per log, each labelled by the safety monitor");
        for (JsonNode r : runs) {
            assertTrue(r.get("log").asText().matches(".*[ab]\\.log#[01]"), r.toString());
            boolean faulty = r.get("faulty").asBoolean();
            assertEquals(r.get("log").asText().endsWith("#1"), faulty, r.toString());
            assertEquals(faulty ? "warned-before-violation" : "quiet", r.get("verdict").asText(), r.toString());
        }
        Abstraction a = AbstractionFiles.defaults();
        LearnedScenario l = ScenarioLearner.learn(new ScenarioSpec("day", false, "",
                List.of(folder.resolve("a.log"), folder.resolve("b.log"))), a);
        assertEquals(4, l.machines().stream().mapToInt(m -> m.samples().size()).sum(), "one sample per run");
    }

    @Test
    @Timeout(60)
    void liveWatchGivesEachRunItsVerdict() throws Exception {
        Path full = day("live-src.log", 51, Scenario.DEPLETED, Scenario.DIRECT, Scenario.DEPLETED);
        Path log = dir.resolve("live.log");
        Files.write(log, new byte[0]);
        Cli.Running watch = Cli.start("watch", "--log", log.toString(), "--models", MODELS.toString(), "--poll-ms", "2",
                "--json");
        StringWriter out = watch.out();
        byte[] bytes = Files.readAllBytes(full);
        for (int from = 0; from < bytes.length; from += 4096) {
            Files.write(log, Arrays.copyOfRange(bytes, from, Math.min(bytes.length, from + 4096)),
                    StandardOpenOption.APPEND);
            Thread.sleep(1);
        }
        long deadline = System.currentTimeMillis() + 20_000;
        while (System.currentTimeMillis() < deadline && !out.toString().contains("\"run\":2,\"time\"")) {
            Thread.sleep(20);
        }
        Thread.sleep(300);
        watch.stop();
        List<JsonNode> warnings = new ArrayList<>();
        for (String line : out.toString().strip().split("\n", -1)) {
            JsonNode e = JSON.readTree(line);
            if (e.get("event").asText().equals("warning")) {
                warnings.add(e);
            }
        }
        assertEquals(ExitCodes.WARNING, watch.code().get(), "stopped after warnings");
        assertEquals(List.of("0 battery", "0 no-abort", "2 battery", "2 no-abort"),
                warnings.stream().map(w -> w.get("run").asInt() + " " + w.get("property").asText()).toList(),
                "the two depleted runs are warned of their battery and their abort, each in its run: " + out);
    }
}
