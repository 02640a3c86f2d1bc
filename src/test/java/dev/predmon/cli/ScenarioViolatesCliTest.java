package dev.predmon.cli;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.model.ModelIndex;
import dev.predmon.model.ModelStore;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import dev.predmon.pipeline.Traces;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A run's outcome is the set of properties it violated, and when; a faulty scenario's {@code scenario.json} may name
 * the property its runs violate, and must name one of the abstraction's.
 */
class ScenarioViolatesCliTest {

    @TempDir
    static Path tmp;
    static Path stuck;

    /** A direct run whose navigation never arrives: 500 ticks stuck, past the 400-tick deadline. */
    @BeforeAll
    static void simulate() {
        stuck = tmp.resolve("stuck.log");
        Cli c = Cli.run("simulate", "--scenario", "direct", "--seed", "7", "--never-arrives", "500", "--out",
                stuck.toString());
        assertEquals(0, c.code(), c.err());
    }

    @Test
    void aRunsOutcomeIsTheSetOfPropertiesItViolatedAndWhen() throws Exception {
        LogTrace t = Traces.read(stuck, AbstractionFiles.defaults());
        LogTrace.Run run = t.runs().get(0);
        assertEquals(List.of("navigation-in-time"), List.copyOf(run.timing().violations().keySet()));
        assertTrue(run.violated("navigation-in-time"));
        assertFalse(run.violated("battery"));
        assertFalse(run.violated(), "the forecast's property, the battery, held");
        RunTiming.Obligation o = run.timing().obligations().stream()
                .filter(x -> x.property().equals("navigation-in-time") && !x.discharged()).findFirst().orElseThrow();
        assertEquals(401.0, o.duration(), "let go at the first tick past its deadline of 400");
    }

    @Test
    void aFaultyScenarioNamesThePropertyItsRunsViolate() throws Exception {
        Path logs = scenario("named", "{\"faulty\": true, \"violates\": \"navigation-in-time\"}");
        ScenarioSpec s = ScenarioLayout.scan(logs, AbstractionFiles.defaults()).get(0);
        assertEquals("navigation-in-time", s.violates());
        LogTrace.Run run = Traces.read(s.logs().get(0), AbstractionFiles.defaults()).runs().get(0);
        assertTrue(s.violatedBy(run), "the thesis's rule is right about this run");
        Path plain = scenario("plain", "{\"faulty\": true}");
        ScenarioSpec p = ScenarioLayout.scan(plain, AbstractionFiles.defaults()).get(0);
        assertNull(p.violates());
        assertFalse(p.violatedBy(run), "by default the property the forecast follows, which held");
    }

    @Test
    void aPropertyTheAbstractionDoesNotDefineIsRefusedAtItsLine() throws Exception {
        Path logs = scenario("typo", "{\"faulty\": true,\n \"violates\": \"navigation\"}");
        Cli c = Cli.run("learn", "--logs", logs.toString(), "--models", tmp.resolve("typo-models").toString());
        assertEquals(ExitCodes.BAD_INPUT, c.code(), c.err());
        List<String> lines = c.err().lines().toList();
        assertEquals(1, lines.size(), c.err());
        assertTrue(lines.get(0).contains(logs.resolve("stuck").resolve("scenario.json") + ":2:14: \"violates\": "
                + "'navigation' is not a property of the abstraction (its properties: "), lines.get(0));
        assertTrue(lines.get(0).contains("navigation-in-time"), lines.get(0));

        Path nominal = scenario("nominal", "{\"faulty\": false, \"violates\": \"navigation-in-time\"}");
        Cli n = Cli.run("learn", "--logs", nominal.toString(), "--models", tmp.resolve("nominal-models").toString());
        assertEquals(ExitCodes.BAD_INPUT, n.code(), n.err());
        assertTrue(n.err().contains("this scenario is not faulty"), n.err());
    }

    /**
     * Trained with stuck runs too, each navigation's held-out forecast meets runs that missed: the deadline's rule is
     * chosen by cross-validation and learn prints its scorecard, counted in obligations.
     */
    @Test
    void learnScoresTheDeadlineWhenTrainingNavigationsMissedIt() throws Exception {
        Path logs = tmp.resolve("mixed");
        assertEquals(0, Cli.run("simulate", "--scenario", "direct", "--runs", "4", "--seed", "21", "--out-dir",
                logs.resolve("direct").toString()).code());
        Path stuckDir = logs.resolve("stuck");
        assertEquals(0, Cli.run("simulate", "--scenario", "direct", "--runs", "4", "--seed", "31", "--never-arrives",
                "500", "--out-dir", stuckDir.toString()).code());
        Files.writeString(stuckDir.resolve("scenario.json"), "{\"faulty\": true, \"violates\": \"navigation-in-time\"}");
        Path models = tmp.resolve("mixed-models");
        Cli c = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString());
        assertEquals(0, c.code(), c.err());
        String card = c.out().lines().filter(l -> l.startsWith("scorecard of 'a navigation ends within 400 ticks'"))
                .findFirst().orElseThrow(() -> new AssertionError(c.out()));
        assertTrue(card.contains("on 8 obligations): warned 4 of 4 missed deadlines, "), card);
        String json = Files.readString(models.resolve("forecast.json"));
        assertTrue(json.contains("\"counted\" : \"obligations\""), json);
        // the models keep which property the faulty scenario is about
        ModelIndex index = ModelStore.read(models, AbstractionFiles.defaults()).index();
        assertEquals("navigation-in-time", index.scenarios().stream().filter(s -> s.name().equals("stuck"))
                .findFirst().orElseThrow().violates());
        assertNull(index.scenarios().stream().filter(s -> s.name().equals("direct")).findFirst().orElseThrow()
                .violates());
        assertFalse(Files.readString(models.resolve("index.json")).contains("\"violates\" : null"));
    }

    /** A log directory with one scenario, {@code stuck}, holding the stuck run and {@code json}. */
    private static Path scenario(String name, String json) throws Exception {
        Path dir = Files.createDirectories(tmp.resolve(name).resolve("stuck"));
        Files.copy(stuck, dir.resolve("stuck-7.log"));
        Files.writeString(dir.resolve("scenario.json"), json);
        return dir.getParent();
    }
}
