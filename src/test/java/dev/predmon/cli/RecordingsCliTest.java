package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import dev.predmon.support.RealLogs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Recordings as users have them: built-in abstractions by name, a flat folder of logs labelled by the safety
 * monitor, and (where {@code ../shared/real-logs} exists) the real monitor's recordings end to end.
 */
class RecordingsCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void builtinAbstractionsByNameAndShow() throws Exception {
        Cli list = Cli.run("abstraction", "list");
        assertEquals(ExitCodes.OK, list.code());
        assertTrue(list.out().contains("thesis") && list.out().contains("scope-fetch"), list.out());
        Cli show = Cli.run("abstraction", "show", "scope-fetch");
        assertEquals(ExitCodes.OK, show.code(), show.err());
        // What 'show' prints is a valid abstraction file: a user starts from it.
        Path file = dir.resolve("mine.json");
        Files.writeString(file, show.out());
        assertEquals(AbstractionFiles.builtin("scope-fetch").orElseThrow().fingerprint(), AbstractionFiles.load(file).fingerprint());
        Cli bad = Cli.run("abstraction", "show", "nope");
        assertEquals(ExitCodes.BAD_INPUT, bad.code());
        assertTrue(bad.err().contains("'nope': not a built-in abstraction (one of thesis, scope-fetch, nav2)"), bad.err());
        Cli missing = Cli.run("learn", "--logs", dir.toString(), "--models", dir.resolve("m").toString(),
                "--abstraction", "scope-fech");
        assertEquals(ExitCodes.BAD_INPUT, missing.code());
        assertTrue(missing.err().contains("scope-fech: cannot read: no such file (nor a built-in abstraction: thesis, scope-fetch, nav2)"), missing.err());
    }

    @Test
    void aFlatFolderIsLabelledByTheSafetyMonitor() throws Exception {
        Path flat = Files.createDirectories(dir.resolve("recordings/2022-10-11"));
        SimOptions o = SimOptions.defaults();
        for (long seed = 1; seed <= 3; seed++) {
            Files.writeString(flat.resolve("run-d" + seed + ".txt"), LogWriter.toText(Simulator.run(Scenario.DEPLETED, seed, o), o));
            Files.writeString(flat.resolve("run-n" + seed + ".log"), LogWriter.toText(Simulator.run(Scenario.DIRECT, seed, o), o));
        }
        Path models = dir.resolve("models");
        Cli learn = Cli.run("learn", "--logs", dir.resolve("recordings").toString(), "--models", models.toString());
        assertEquals(ExitCodes.OK, learn.code(), learn.err());
        JsonNode index = JSON.readTree(models.resolve("index.json").toFile());
        String text = index.toString();
        assertTrue(text.contains("\"violating\"") && text.contains("\"safe\""), text);
        assertTrue(learn.out().contains("scenario safe (nominal): 3 run(s)"), learn.out());
        assertTrue(learn.out().contains("scenario violating (faulty): 3 run(s)"), learn.out());
        Cli folds = Cli.run("evaluate", "--logs", dir.resolve("recordings").toString(), "--folds", "3", "--quiet");
        assertEquals(ExitCodes.OK, folds.code(), folds.err());
        assertTrue(folds.out().contains("violating") && folds.out().contains("safe"), folds.out());
    }

    /**
     * Learned on the recordings with scope-fetch, under cross-validation: every violation the battery approached is
     * warned before it, and a safe run is warned only beyond what the safe runs did: in behaviour no model has seen,
     * or with every nominal machine eliminated, or below the lowest value a safe training run read (at most one: the
     * safe run that went lower than every other).
     */
    @Test
    void realRecordingsCrossValidateWithoutFalseAlarms() throws Exception {
        List<RealLogs.Row> rows = RealLogs.rows();
        Cli r = Cli.run("evaluate", "--logs", RealLogs.DIR.toString(), "--folds", "5", "--abstraction", "scope-fetch",
                "--json", "--quiet");
        assertEquals(ExitCodes.OK, r.code(), r.err());
        JsonNode e = JSON.readTree(r.out());
        int runs = 0;
        int falseAlarms = 0;
        for (JsonNode s : e.get("scenarios")) {
            runs += s.get("runs").asInt();
            falseAlarms += s.get("falseAlarms").asInt();
        }
        assertTrue(falseAlarms <= 1, r.out());
        for (JsonNode run : e.get("runs")) {
            if (run.get("verdict").asText().equals("false-alarm")) {
                // only beyond what the safe runs did: novel, every nominal machine eliminated by then, or the value
                // below the lowest a safe training run read (the raw-value rule, which every rule keeps)
                double at = run.get("warningTime").asDouble();
                JsonNode raw = run.get("forecast").get("valueRule");
                boolean nominalGone = false;
                for (JsonNode x : run.get("eliminations")) {
                    nominalGone |= !x.get("faulty").asBoolean() && x.get("time").asDouble() <= at;
                }
                assertTrue(nominalGone || run.get("forecast").get("atWarning").get("novelSince").isNumber()
                        || (raw.isNumber() && raw.asDouble() <= at), run.toString());
            }
        }
        assertEquals(rows.size(), runs);
        long violating = rows.stream().filter(x -> x.violationTick().isPresent()).count();
        long approached = 0;
        long hits = 0;
        for (JsonNode run : e.get("runs")) {
            assertEquals("ticks", run.get("unit").asText());
            assertTrue(run.get("forecast").get("probabilities").size() > 0, "every run has a forecast: " + run);
            JsonNode before = run.get("beforeViolation");
            if (run.get("faulty").asBoolean() && before.isNumber() && before.asDouble() <= 25) {
                // A violation the battery approached (no jump straight past 25%) is one a predictive monitor is for.
                approached++;
                hits += run.get("verdict").asText().equals("warned-before-violation") ? 1 : 0;
            }
        }
        assertTrue(violating > 0 && approached > 0, r.out());
        assertEquals(approached, hits, "every approached violation is warned: " + r.out());
    }

    @Test
    void watchCountsEveryRecordOfARealRecording() throws Exception {
        RealLogs.Row row = RealLogs.rows().get(0);
        Path models = dir.resolve("models");
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", RealLogs.DIR.toString(), "--models", models.toString(),
                "--abstraction", "scope-fetch").code());
        Cli w = Cli.run("watch", "--log", row.path().toString(), "--models", models.toString(),
                "--abstraction", "scope-fetch", "--no-follow", "--json");
        String[] lines = w.out().strip().split("\n", -1);
        JsonNode end = JSON.readTree(lines[lines.length - 1]);
        assertEquals("end", end.get("event").asText());
        assertEquals(row.commands() + row.replies() + row.ticks(), end.get("records").asLong());
        assertEquals("ticks", end.get("unit").asText());
    }
}
