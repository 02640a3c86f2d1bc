package dev.predmon.cli;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioSpec;
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
                .filter(x -> x.property().equals("navigation-in-time") && x.missed()).findFirst().orElseThrow();
        assertEquals(400.0, o.deadline());
        double[] steps = o.steps();
        assertEquals(0.0, steps[0], "forecast from the record that made the obligation");
        assertEquals(400.0, steps[steps.length - 1], "and after every record until the one past its deadline");
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

    /** A log directory with one scenario, {@code stuck}, holding the stuck run and {@code json}. */
    private static Path scenario(String name, String json) throws Exception {
        Path dir = Files.createDirectories(tmp.resolve(name).resolve("stuck"));
        Files.copy(stuck, dir.resolve("stuck-7.log"));
        Files.writeString(dir.resolve("scenario.json"), json);
        return dir.getParent();
    }
}
