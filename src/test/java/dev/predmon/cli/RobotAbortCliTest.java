package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.support.RealLogs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What the real robot does: its navigation to the charging station aborts at about 25% battery, and the battery
 * drains to the violation some 25 ticks later. The run is made in memory from the public recording of the safe run
 * that went lowest (it recharged): from the tick its battery comes within a point of its lowest, each tick is
 * repeated with {@code getStatus} answering ABORT and the level falling 0.2 per tick. Models are learned from the
 * public recordings, as a user would; the run is behaviour none of them has seen.
 */
class RobotAbortCliTest {

    private static final String ANSI = "\u001B\\[[0-9;]*m";

    @TempDir
    Path tmp;

    @Test
    void anAbortedNavigationToTheChargerIsWarnedWellBeforeTheViolation() throws Exception {
        RealLogs.Row lowest = RealLogs.rows().stream().filter(r -> r.violationTick().isEmpty())
                .min(Comparator.comparingDouble(RealLogs.Row::lowestLevel)).orElseThrow();
        Path log = tmp.resolve("aborted.txt");
        Files.writeString(log, aborted(Files.readAllLines(lowest.path(), StandardCharsets.ISO_8859_1),
                lowest.lowestLevel() + 1.0), StandardCharsets.ISO_8859_1);
        Path models = tmp.resolve("models");
        Cli learned = Cli.run("learn", "--logs", RealLogs.DIR.toString(), "--abstraction", "scope-fetch",
                "--models", models.toString());
        assertEquals(ExitCodes.OK, learned.code(), learned.err());

        Cli w = Cli.run("watch", "--no-follow", "--json", "--log", log.toString(), "--models", models.toString());
        List<JsonNode> events = w.jsonLines();
        JsonNode noMatch = Cli.firstEvent(events, "no-match").orElse(null);
        JsonNode warning = Cli.firstEvent(events, "warning").orElse(null);
        JsonNode violation = events.stream().filter(e -> e.get("event").asText().equals("violation")
                && e.get("property").asText().equals("battery")).findFirst().orElse(null);
        assertNotNull(noMatch, "the abort is behaviour no model has seen: " + w.out());
        assertNotNull(violation, "the battery drains past 20");
        assertNotNull(warning, "warned: " + w.out());
        double lead = violation.get("time").asDouble() - warning.get("time").asDouble();
        assertTrue(lead >= 15, "warned " + lead + " ticks ahead, not at the last moment: " + warning);
        assertEquals("ticks", warning.get("unit").asText());
        assertTrue(warning.get("reason").asText().contains("novel behaviour since"), warning.toString());
    }

    /** The recording up to the first tick whose level reading is at most {@code level}, then that tick aborted. */
    static String aborted(List<String> lines, double level) {
        List<Integer> ticks = new ArrayList<>();
        int from = -1;
        double start = Double.NaN;
        for (int i = 0; i + 6 < lines.size(); i++) {
            String head = plain(lines.get(i));
            if (head.contains("Tick intercepted")) {
                ticks.add(i);
            } else if (from < 0 && head.contains("Reply intercepted") && plain(lines.get(i + 4)).endsWith(": level")) {
                double v = Double.parseDouble(value(lines.get(i + 6)));
                if (v <= level && !ticks.isEmpty()) {
                    from = ticks.get(ticks.size() - 1);
                    start = v;
                }
            }
        }
        assertTrue(from >= 0, "the recording reads a level below " + level);
        int to = from + 1;
        while (to < lines.size() && !plain(lines.get(to)).contains("Tick intercepted")) {
            to++;
        }
        List<String> block = lines.subList(from, to);
        long tick = Long.parseLong(value(block.get(5)));
        StringBuilder out = new StringBuilder();
        lines.subList(0, from).forEach(l -> out.append(l).append('\n'));
        for (int k = 0; k < 40; k++) {
            for (int j = 0; j < block.size(); j++) {
                String l = block.get(j);
                String p = plain(l);
                if (j == 5) {
                    l = "  Arguments : " + (tick + k);
                } else if (j >= 6 && p.startsWith("  Reply     : ") && plain(block.get(j - 2)).endsWith(": level")) {
                    l = String.format(Locale.ROOT, "  Reply     : %.4f", start - 0.2 * k);
                } else if (j >= 6 && p.startsWith("  Reply     : ") && plain(block.get(j - 2)).endsWith(": getStatus")
                        && k > 0) {
                    l = "  Reply     : 3";
                }
                out.append(l).append('\n');
            }
        }
        return out.toString();
    }

    private static String plain(String line) {
        return line.replaceAll(ANSI, "");
    }

    private static String value(String line) {
        String p = plain(line);
        return p.substring(p.indexOf(": ") + 2).trim();
    }
}
