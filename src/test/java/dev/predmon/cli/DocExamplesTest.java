package dev.predmon.cli;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The documentation's examples are what the shipped models print: the lines docs/forecast.md and docs/watch.md show
 * of the demo's depleted run ({@code simulate --scenario depleted --seed 9001}) come out of the commands they name,
 * verbatim (the JSON lines abridged at their {@code ...}, without {@code wallTime}, as the page says).
 */
class DocExamplesTest {

    @TempDir
    static Path tmp;
    private static Path log;

    @BeforeAll
    static void simulate() throws Exception {
        log = tmp.resolve("depleted-9001.log");
        Cli r = Cli.run("simulate", "--scenario", "depleted", "--seed", "9001", "--out", log.toString());
        assertEquals(0, r.code(), r.err());
    }

    /** The lines of the fenced block that follows {@code after} in {@code doc}. */
    private static List<String> block(String doc, String after) throws Exception {
        String text = Files.readString(Path.of("docs", doc));
        int at = text.indexOf(after);
        assertTrue(at >= 0, doc + " no longer says: " + after);
        int start = text.indexOf('\n', text.indexOf("```", at)) + 1;
        return List.of(text.substring(start, text.indexOf("```", start)).strip().split("\n"));
    }

    @Test
    void theForecastPagesExampleIsWhatWatchPrints() throws Exception {
        List<String> shown = block("forecast.md", "`watch --log depleted-9001.log --no-follow --eliminations`");
        Cli r = Cli.run("watch", "--log", log.toString(), "--no-follow", "--eliminations");
        List<String> printed = r.out().lines().toList();
        assertEquals(2, shown.size(), shown.toString());
        for (String line : shown) {
            assertTrue(printed.contains(line), "docs/forecast.md shows a line watch does not print:\n" + line
                    + "\nwatch prints:\n" + String.join("\n", printed.stream().filter(l -> l.startsWith(
                    line.substring(0, line.indexOf(':')))).toList()));
        }
    }

    @Test
    void theEventsPagesJsonIsWhatWatchPrints() throws Exception {
        List<String> shown = block("watch.md", "`watch --log depleted-9001.log --no-follow --json`), abridged");
        Cli r = Cli.run("watch", "--log", log.toString(), "--no-follow", "--json");
        String printed = r.out().replaceAll(",\"wallTime\":\"[^\"]*\"", "");
        List<String> missing = new ArrayList<>();
        for (String line : shown) {
            for (String part : line.split("\\.\\.\\.", -1)) {
                if (part.length() >= 3 && !printed.contains(part)) {
                    missing.add(part);
                }
            }
            if (line.startsWith("{\"event\":\"end\"")) {
                break; // the lines after it show rarer events of other logs
            }
        }
        assertEquals(List.of(), missing, "docs/watch.md shows what watch --json does not print");
    }
}
