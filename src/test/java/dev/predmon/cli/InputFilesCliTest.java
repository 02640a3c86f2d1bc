package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The files around the commands: scenario.json is read strictly, simulate does not rewrite a scenario.json that
 * says something else, and demo and export-samples leave nothing behind when they fail or finish.
 */
class InputFilesCliTest {

    @TempDir
    Path tmp;

    private Path logsWithScenarioJson(String json) throws Exception {
        Path logs = tmp.resolve("logs");
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        Files.writeString(logs.resolve("recharge/scenario.json"), json);
        return logs;
    }

    /** One stderr line, exit 3. */
    private static void oneLine(Cli r, String expected) {
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
        assertEquals(List.of("predmon: " + expected), r.err().strip().lines().toList());
    }

    @Test
    void aMisspelledKeyInScenarioJsonIsRejectedWhereItIs() throws Exception {
        Path logs = logsWithScenarioJson("{\n  \"faulty\": false,\n  \"descripton\": \"charges on the way\"\n}\n");
        Path json = logs.resolve("recharge/scenario.json");
        String expected = json + ":3:3: unknown key 'descripton' (allowed: description, faulty, violates)";
        oneLine(Cli.run("learn", "--logs", logs.toString(), "--models", tmp.resolve("models").toString()), expected);
        oneLine(Cli.run("evaluate", "--logs", logs.toString(), "--folds", "2", "--quiet"), expected);
        oneLine(Cli.run("export-samples", "--logs", logs.toString(), "--out", tmp.resolve("samples").toString()), expected);
        assertFalse(Files.exists(tmp.resolve("models")), "nothing learned");
    }

    @Test
    void aFaultyFlagThatIsNotABooleanIsRejected() throws Exception {
        Path logs = logsWithScenarioJson("{\"faulty\": \"no\", \"description\": \"x\"}");
        Cli r = Cli.run("learn", "--logs", logs.toString(), "--models", tmp.resolve("models").toString());
        oneLine(r, logs.resolve("recharge/scenario.json") + ":1:12: \"faulty\": expected true or false");
    }

    /** simulate --scenario depleted --out-dir runs/direct: the nominal scenario.json stays, no run is written. */
    @Test
    void simulateDoesNotRewriteAScenarioJsonThatSaysSomethingElse() throws Exception {
        Path direct = tmp.resolve("runs/direct");
        assertEquals(ExitCodes.OK, Cli.run("simulate", "--scenario", "direct", "--runs", "2", "--out-dir", direct.toString()).code());
        String before = Files.readString(direct.resolve("scenario.json"));
        Cli r = Cli.run("simulate", "--scenario", "depleted", "--runs", "2", "--out-dir", direct.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains(direct.resolve("scenario.json") + ": says faulty: false"), r.err());
        assertEquals(before, Files.readString(direct.resolve("scenario.json")));
        try (Stream<Path> s = Files.list(direct)) {
            assertTrue(s.noneMatch(p -> p.getFileName().toString().startsWith("depleted")), "no depleted run written");
        }
        // more runs of the same scenario are fine
        assertEquals(ExitCodes.OK, Cli.run("simulate", "--scenario", "direct", "--seed", "3", "--out-dir", direct.toString()).code());
        assertEquals(before, Files.readString(direct.resolve("scenario.json")));
    }

    @Test
    void demoSecondsZeroIsAUsageErrorWithoutStackTraces() {
        for (String seconds : List.of("0", "-1", "Infinity", "NaN")) {
            Cli r = Cli.run("demo", "--seconds", seconds);
            assertEquals(ExitCodes.USAGE, r.code(), seconds);
            assertTrue(r.err().startsWith("predmon: --seconds must be a positive number, got "), r.err());
            assertFalse(r.err().contains("Exception") || r.out().contains("Infinityx"), r.out() + r.err());
        }
    }

    /** Without --work, demo writes into a temporary directory of its own and removes it. */
    @Test
    void demoRemovesItsTemporaryDirectory() {
        Cli r = Cli.run("demo", "--seconds", "0.5");
        assertEquals(ExitCodes.OK, r.code(), r.out() + r.err());
        Matcher m = Pattern.compile("into (\\S+)/depleted-9001\\.log").matcher(r.out());
        assertTrue(m.find(), r.out());
        Path dir = Path.of(m.group(1));
        assertTrue(dir.getFileName().toString().startsWith("predmon-demo-"), dir.toString());
        assertFalse(Files.exists(dir), dir + " is removed");
    }

    /** The log writer runs on a thread of its own: its failure is the command's, one line and exit 3. */
    @Test
    void demoReportsItsWriterFailing() throws Exception {
        Path work = Files.createDirectories(tmp.resolve("work"));
        Files.setPosixFilePermissions(work, PosixFilePermissions.fromString("r-xr-xr-x"));
        try {
            Child r = Child.runBoundByPermissions(tmp, "demo", "--seconds", "0.5", "--work", work.toString(),
                    "--models", Path.of("models").toAbsolutePath().toString());
            assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
            assertEquals(List.of("predmon: " + work.resolve("depleted-9001.log") + ": permission denied"),
                    r.err().strip().lines().toList());
        } finally {
            Files.setPosixFilePermissions(work, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    /** export-samples that fails on a bad log directory leaves no empty --out (nor its parents) behind. */
    @Test
    void exportSamplesLeavesNoEmptyOut() throws Exception {
        Path logs = logsWithScenarioJson("{\"faulty\": false, \"colour\": \"red\"}");
        Path out = tmp.resolve("exports/samples");
        Cli r = Cli.run("export-samples", "--logs", logs.toString(), "--out", out.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.err());
        assertFalse(Files.exists(tmp.resolve("exports")), "no --out and no parent of it created");
    }
}
