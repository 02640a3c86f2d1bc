package dev.predmon.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.report.HtmlReport;
import dev.predmon.samples.SampleFile;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A disk that fills while predmon writes, as {@code ulimit -f} makes it happen to a real process: every file it
 * writes (models, report, samples, simulated log) is written completely or the command fails with exit 3 and one
 * line naming the file, and the previous file is left byte for byte as it was, with nothing beside it.
 */
class FileSizeLimitTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path tmp;

    /** Two logs of each sample scenario: enough to learn and cross-validate, small enough to be quick. */
    private Path smallLogs() throws IOException {
        Path logs = tmp.resolve("logs");
        for (String scenario : List.of("direct", "recharge", "depleted")) {
            Path from = Path.of("sample-logs", scenario);
            Path to = Files.createDirectories(logs.resolve(scenario));
            for (String name : List.of("scenario.json", scenario + "-1.log", scenario + "-2.log")) {
                Files.copy(from.resolve(name), to.resolve(name));
            }
        }
        return logs;
    }

    /** Exit 3 and exactly one line on stderr, naming {@code file} and saying it was not written. */
    private static void failedNaming(Child r, String file) {
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
        List<String> lines = r.err().strip().lines().toList();
        assertEquals(1, lines.size(), r.err());
        assertTrue(lines.get(0).startsWith("predmon: " + file + ": not written ("), r.err());
    }

    /**
     * The built-in abstraction with a description 4,000 characters longer: the index, which holds the abstraction
     * as well, grows past the forecast, so that a limit between them stops learn at the index, its last file.
     */
    private static Path longerAbstraction(Path dir) throws Exception {
        Cli shown = Cli.run("abstraction", "show", "thesis");
        assertEquals(0, shown.code(), shown.err());
        ObjectNode a = (ObjectNode) JSON.readTree(shown.out());
        a.put("description", a.get("description").asText() + " " + "padding ".repeat(500).strip());
        return Files.writeString(dir.resolve("longer.json"), JSON.writeValueAsString(a));
    }

    /**
     * learn's index.json is larger than the limit: learn fails naming it, the previous models are all there as
     * they were, and the next learn (with room) replaces them as usual.
     */
    @Test
    void learnThatCannotWriteItsIndexKeepsThePreviousModels(@TempDir Path elsewhere) throws Exception {
        Path logs = smallLogs();
        String abstraction = longerAbstraction(elsewhere).toString();
        Path previousLogs = tmp.resolve("previous");
        Files.createDirectories(previousLogs);
        copyDir(logs.resolve("direct"), previousLogs.resolve("direct"));
        assertEquals(0, Child.run(tmp, "learn", "--logs", "previous", "--models", "models", "--abstraction",
                abstraction).code());
        Map<String, String> before = snapshot(tmp.resolve("models"));
        // 12 KiB: the abstraction with its properties fits, and so does the forecast of the logs (written before
        // the index), but the index (which holds the abstraction too) does not
        assertTrue(Files.size(tmp.resolve("models/index.json")) > 12288, "the index is larger than the limit");
        assertTrue(Files.size(tmp.resolve("models/abstraction.json")) < 12288, "the abstraction is not");

        Child r = Child.runWithFileSizeLimit(tmp, 12, "learn", "--logs", "logs", "--models", "models",
                "--abstraction", abstraction);
        failedNaming(r, "models/index.json");
        assertTrue(r.err().contains("the previous models are unchanged"), r.err());
        assertEquals(before, snapshot(tmp.resolve("models")));
        assertEquals(List.of("logs", "models", "previous"), names(tmp), "no staging or set-aside directory is left");

        Child again = Child.run(tmp, "learn", "--logs", "logs", "--models", "models", "--abstraction", abstraction);
        assertEquals(0, again.code(), again.err());
        assertTrue(Files.isRegularFile(tmp.resolve("models/depleted.dot")));
    }

    @Test
    void aReportThatDoesNotFitLeavesThePreviousReport() throws Exception {
        smallLogs();
        String previous = HtmlReport.SIGNATURE + "\n<p>yesterday's evaluation</p>\n";
        Path report = Files.writeString(Files.createDirectories(tmp.resolve("out")).resolve("report.html"), previous);
        Child r = Child.runWithFileSizeLimit(tmp, 64, "evaluate", "--logs", "logs", "--folds", "2", "--quiet",
                "--report", "out/report.html");
        failedNaming(r, "out/report.html");
        assertEquals(previous, Files.readString(report));
        assertEquals(List.of("report.html"), names(tmp.resolve("out")), "no temporary file is left");
    }

    @Test
    void samplesThatDoNotFitLeaveThePreviousSamples() throws Exception {
        smallLogs();
        String previous = SampleFile.SIGNATURE + "\n# scenario: depleted\n";
        Path samples = Files.writeString(Files.createDirectories(tmp.resolve("samples")).resolve("depleted.txt"),
                previous);
        Child r = Child.runWithFileSizeLimit(tmp, 1, "export-samples", "--logs", "logs", "--out", "samples");
        failedNaming(r, "samples/depleted.txt");
        assertEquals(previous, Files.readString(samples));
        assertEquals(List.of("depleted.txt"), names(tmp.resolve("samples")), "no temporary file is left");
    }

    @Test
    void aSimulatedLogThatDoesNotFitLeavesThePreviousLog() throws Exception {
        Path log = Files.writeString(tmp.resolve("run.log"), "yesterday's run\n");
        Child r = Child.runWithFileSizeLimit(tmp, 16, "simulate", "--scenario", "direct", "--out", "run.log");
        failedNaming(r, "run.log");
        assertEquals("yesterday's run\n", Files.readString(log));

        Path dir = Files.createDirectories(tmp.resolve("runs"));
        Files.writeString(dir.resolve("direct-1.log"), "yesterday's run\n");
        Child batch = Child.runWithFileSizeLimit(tmp, 16, "simulate", "--scenario", "direct", "--runs", "2",
                "--out-dir", "runs");
        failedNaming(batch, "runs/direct-1.log");
        assertEquals(Map.of("direct-1.log", "yesterday's run\n"), snapshot(dir));
    }

    /**
     * A log and its truth sidecar are replaced as a pair: when the log does not fit, the previous truth stays beside
     * the previous log (a new truth was written first, beside the old log), and the line says so.
     */
    @Test
    void aSimulatedLogAndItsTruthAreReplacedAsAPair() throws Exception {
        Path log = Files.writeString(tmp.resolve("run.log"), "yesterday's run\n");
        Path truth = Files.writeString(tmp.resolve("run.log.truth.json"), "{\"seed\": 7}\n");
        Child r = Child.runWithFileSizeLimit(tmp, 16, "simulate", "--scenario", "direct", "--out", "run.log");
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
        assertEquals("predmon: run.log: not written (file too large); the previous run.log and run.log.truth.json "
                + "are unchanged", r.err().strip());
        assertEquals("yesterday's run\n", Files.readString(log));
        assertEquals("{\"seed\": 7}\n", Files.readString(truth));
        assertEquals(List.of("run.log", "run.log.truth.json"), names(tmp), "no temporary file is left");

        Child day = Child.runWithFileSizeLimit(tmp, 16, "simulate", "--scenario", "direct,depleted", "--runs", "4",
                "--out", "run.log");
        assertEquals(ExitCodes.BAD_INPUT, day.code(), day.out() + day.err());
        assertEquals("{\"seed\": 7}\n", Files.readString(truth));
        assertEquals(List.of("run.log", "run.log.truth.json"), names(tmp), "no temporary file is left");

        Child fits = Child.run(tmp, "simulate", "--scenario", "direct", "--out", "run.log");
        assertEquals(0, fits.code(), fits.err());
        assertTrue(Files.readString(truth).contains("\"scenario\" : \"direct\""), Files.readString(truth));
    }

    /** A live log is written in place (a monitor tails it): when it stops, the line names it and says so. */
    @Test
    void aLiveSimulatedLogThatDoesNotFitIsNamed() throws Exception {
        Child r = Child.runWithFileSizeLimit(tmp, 16, "simulate", "--scenario", "direct", "--realtime", "--speed",
                "1000", "--out", "live.log");
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
        assertEquals("predmon: live.log: writing stopped (file too large); it holds the records written before",
                r.err().strip());
        assertEquals(16 * 1024, Files.size(tmp.resolve("live.log")));
    }

    private static void copyDir(Path from, Path to) throws IOException {
        Files.createDirectories(to);
        try (Stream<Path> s = Files.list(from)) {
            for (Path p : s.toList()) {
                Files.copy(p, to.resolve(p.getFileName()));
            }
        }
    }

    private static List<String> names(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    private static Map<String, String> snapshot(Path dir) throws IOException {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : s.toList()) {
                m.put(p.getFileName().toString(), Files.readString(p, StandardCharsets.ISO_8859_1));
            }
        }
        return m;
    }
}
