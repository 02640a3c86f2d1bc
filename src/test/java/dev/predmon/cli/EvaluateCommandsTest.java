package dev.predmon.cli;

import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** evaluate, explain, export-samples and bench in-process, with tiny sizes. */
class EvaluateCommandsTest {

    @TempDir
    Path dir;

    private Path logs(String name, int runs, long seed) throws Exception {
        Path root = dir.resolve(name);
        for (Scenario s : Scenario.values()) {
            Path d = Files.createDirectories(root.resolve(s.id()));
            Files.writeString(d.resolve("scenario.json"), "{\"faulty\": " + s.faulty() + "}");
            for (long k = seed; k < seed + runs; k++) {
                Files.writeString(d.resolve(s.id() + "-" + k + ".log"),
                        LogWriter.toText(Simulator.run(s, k, SimOptions.defaults()), SimOptions.defaults()));
            }
        }
        return root;
    }

    @Test
    void evaluateWithATestSetPrintsTheTableAndWritesTheReport() throws Exception {
        Path report = dir.resolve("out/report.html");
        Cli r = Cli.run("evaluate", "--logs", logs("a", 3, 1).toString(), "--test", logs("b", 1, 900).toString(),
                "--report", report.toString(), "--quiet");
        assertEquals(ExitCodes.OK, r.code(), r.err());
        assertTrue(r.out().contains("depleted") && r.out().contains("false") && r.out().contains("lead: median"), r.out());
        assertTrue(Files.readString(report).startsWith("<!DOCTYPE html>"));
    }

    @Test
    void evaluateJsonAndBadFolds() throws Exception {
        Path a = logs("a", 2, 1);
        Cli r = Cli.run("evaluate", "--logs", a.toString(), "--folds", "2", "--json");
        assertEquals(ExitCodes.OK, r.code(), r.err());
        assertTrue(r.out().contains("\"mode\" : \"cross-validation\""), r.out());
        assertEquals(ExitCodes.USAGE, Cli.run("evaluate", "--logs", a.toString(), "--folds", "1").code());
        assertEquals(ExitCodes.USAGE, Cli.run("evaluate", "--logs", a.toString(), "--folds", "2", "--test", a.toString()).code());
        assertEquals(ExitCodes.BAD_INPUT, Cli.run("evaluate", "--logs", dir.resolve("nope").toString()).code());
    }

    @Test
    void explainAndExport() throws Exception {
        Path a = logs("a", 2, 1);
        Path models = dir.resolve("models");
        assertEquals(ExitCodes.OK, Cli.run("learn", "--logs", a.toString(), "--models", models.toString()).code());
        Cli x = Cli.run("explain", "--log", a.resolve("direct/direct-1.log").toString(), "--models", models.toString());
        assertEquals(ExitCodes.OK, x.code(), x.err());
        assertTrue(x.out().contains("matches the whole run") && x.out().contains("does not warn"), x.out());
        Path out = dir.resolve("samples");
        Cli e = Cli.run("export-samples", "--logs", a.toString(), "--out", out.toString());
        assertEquals(ExitCodes.OK, e.code(), e.err());
        assertTrue(Files.readString(out.resolve("direct.txt")).contains("# scenario: direct"));
    }

    @Test
    void benchPrintsEveryFigureWithTinySizes() {
        Cli r = Cli.run("bench", "--batch-mb", "1", "--latency-runs", "3", "--memory-records", "20000",
                "--learn-runs", "2", "--model-runs", "2", "--fleet-logs", "1,3", "--fleet-samples", "3",
                "--fleet-seconds", "0.2", "--fleet-idle-logs", "20", "--tmp", dir.toString());
        assertEquals(ExitCodes.OK, r.code(), r.err());
        for (String figure : new String[] {"batch: parse", "grep -c", "latency:", "latency without the forecast",
            "p99 with the forecast / without", "watch cpu:", "watch heap:", "learn: 2 runs",
            "latency: append of the warning's record -> warning event, 3 runs",
            "fleet: 1 log in one process, woken by file-change notification", "(3 samples)",
            "fleet: 3 logs in one process, woken by file-change notification",
            "fleet idle: 20 logs of 12 records in one process, woken by file-change notification"}) {
            assertTrue(r.out().contains(figure), figure + " in\n" + r.out());
        }
        Cli polling = Cli.run("bench", "--only", "fleet", "--fleet-polling", "--fleet-samples", "3",
                "--model-runs", "2", "--fleet-logs", "2", "--fleet-seconds", "0.2", "--fleet-idle-logs", "0", "--tmp",
                dir.toString());
        assertEquals(ExitCodes.OK, polling.code(), polling.err());
        assertTrue(polling.out().contains("fleet: 2 logs in one process, polling every 1000 us"), polling.out());
        assertEquals(ExitCodes.USAGE, Cli.run("bench", "--only", "nonsense").code());
    }
}
