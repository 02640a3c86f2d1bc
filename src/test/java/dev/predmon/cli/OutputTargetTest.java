package dev.predmon.cli;

import dev.predmon.report.HtmlReport;
import dev.predmon.samples.SampleFile;
import org.junit.jupiter.api.BeforeEach;
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
 * {@code evaluate --report FILE} and {@code export-samples --out DIR} never write over an input or a file predmon
 * did not write: the output is checked before any work starts (nothing is printed, nothing learned), refused with
 * exit 3 and one line naming it, and every file is left as it was. Their own earlier outputs they replace.
 */
class OutputTargetTest {

    @TempDir
    Path tmp;
    Path logs;

    @BeforeEach
    void logs() throws IOException {
        logs = tmp.resolve("logs");
        for (String scenario : List.of("direct", "depleted")) {
            Path from = Path.of("sample-logs", scenario);
            Path to = Files.createDirectories(logs.resolve(scenario));
            for (String name : List.of("scenario.json", scenario + "-1.log", scenario + "-2.log")) {
                Files.copy(from.resolve(name), to.resolve(name));
            }
        }
    }

    /** Refused before the work: exit 3, one line naming {@code named} and saying {@code what}, nothing changed. */
    private void refused(Cli r, Map<String, String> before, Path named, String what) throws IOException {
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
        List<String> lines = r.err().strip().lines().toList();
        assertEquals(1, lines.size(), r.err());
        assertTrue(lines.get(0).startsWith("predmon: " + named + ": ") && lines.get(0).contains(what), r.err());
        assertEquals("", r.out(), "refused before any work: nothing evaluated or learned");
        assertEquals(before, snapshot(tmp), "nothing touched");
    }

    private Cli evaluate(Path report) {
        return Cli.run("evaluate", "--logs", logs.toString(), "--folds", "2", "--quiet", "--report", report.toString());
    }

    @Test
    void aReportOverATrainingLogIsRefused() throws Exception {
        Path log = logs.resolve("direct/direct-1.log");
        refused(evaluate(log), snapshot(tmp), log, "is inside " + logs + ", the input given as --logs");
    }

    @Test
    void aReportOverAModelIndexIsRefused() throws Exception {
        assertEquals(0, Cli.run("learn", "--logs", logs.toString(), "--models", tmp.resolve("models").toString()).code());
        Path index = tmp.resolve("models/index.json");
        refused(evaluate(index), snapshot(tmp), index, "is not an evaluate report predmon wrote");
    }

    @Test
    void aReportOverAUsersPageIsRefusedButItsOwnReportIsReplaced() throws Exception {
        Path page = Files.writeString(tmp.resolve("index.html"), "<!DOCTYPE html>\n<p>my lab's page</p>\n");
        refused(evaluate(page), snapshot(tmp), page, "is not an evaluate report predmon wrote");

        Path report = Files.writeString(tmp.resolve("report.html"), HtmlReport.SIGNATURE + "\n<p>yesterday</p>");
        Cli r = evaluate(report);
        assertEquals(0, r.code(), r.err());
        assertTrue(Files.readString(report).startsWith(HtmlReport.SIGNATURE) && Files.size(report) > 10_000);
    }

    /** A folder of recordings given as --logs and --out: the samples would land among the recordings. */
    @Test
    void samplesIntoTheLogsAreRefused() throws Exception {
        Path recordings = Files.createDirectories(tmp.resolve("recordings"));
        Files.copy(logs.resolve("direct/direct-1.log"), recordings.resolve("2024-05-01.log"));
        Files.copy(logs.resolve("depleted/depleted-1.log"), recordings.resolve("2024-05-02.log"));
        refused(Cli.run("export-samples", "--logs", recordings.toString(), "--out", recordings.toString()),
                snapshot(tmp), recordings, "is the input given as --logs");
    }

    /**
     * --out names a folder where a file is called as a sample file would be ({@code safe.txt}, a recording of a
     * safe run), but is not one: refused before learning, and no other sample file is written either.
     */
    @Test
    void samplesOverAFileThatIsNoSampleFileAreRefused() throws Exception {
        Path recordings = Files.createDirectories(tmp.resolve("recordings"));
        Files.copy(logs.resolve("direct/direct-1.log"), recordings.resolve("2024-05-01.log"));
        Files.copy(logs.resolve("depleted/depleted-1.log"), recordings.resolve("2024-05-02.log"));
        Path fleet = Files.createDirectories(tmp.resolve("fleet"));
        Path safe = Files.copy(logs.resolve("direct/direct-2.log"), fleet.resolve("safe.txt"));
        refused(Cli.run("export-samples", "--logs", recordings.toString(), "--out", fleet.toString()),
                snapshot(tmp), safe, "is not a sample file predmon wrote");
    }

    @Test
    void samplesReplaceTheSamplesOfAnEarlierExport() throws Exception {
        Path out = tmp.resolve("samples");
        assertEquals(0, Cli.run("export-samples", "--logs", logs.toString(), "--out", out.toString()).code());
        Files.writeString(out.resolve("direct.txt"), SampleFile.SIGNATURE + "\n# scenario: direct\n");
        Cli again = Cli.run("export-samples", "--logs", logs.toString(), "--out", out.toString());
        assertEquals(0, again.code(), again.err());
        assertEquals(2, SampleFile.read(out.resolve("direct.txt")).size(), "rewritten with both runs");
    }

    private static Map<String, String> snapshot(Path dir) throws IOException {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted().toList()) {
                m.put(dir.relativize(p).toString(), Files.isRegularFile(p)
                        ? Files.readString(p, StandardCharsets.ISO_8859_1) : "<dir>");
            }
        }
        return m;
    }
}
