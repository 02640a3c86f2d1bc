package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code evaluate} scores every property's forecast (Brier score against the base rate, calibration error, the
 * reliability table) in the text, the JSON and the HTML report; and a faulty scenario's matching warning names the
 * property its {@code scenario.json} says it violates, in the event, the hooks and evaluate's row of that property.
 */
class PropertyScoresCliTest {

    @TempDir
    static Path tmp;
    static Path train;
    static Path stuck;

    /** Six default runs of each scenario to learn from; two of each whose way to the tour location is blocked. */
    @BeforeAll
    static void simulate() throws Exception {
        train = tmp.resolve("train");
        stuck = tmp.resolve("stuck");
        for (String s : List.of("direct", "recharge", "depleted")) {
            String json = "{\"faulty\": " + s.equals("depleted") + "}";
            simulate(train.resolve(s), json, "--scenario", s, "--runs", "6", "--seed", "501");
            simulate(stuck.resolve(s), json, "--scenario", s, "--runs", "2", "--seed", "9001", "--never-arrives",
                    "500");
        }
    }

    private static void simulate(Path dir, String scenarioJson, String... args) throws Exception {
        List<String> all = new ArrayList<>(List.of("simulate", "--out-dir", dir.toString()));
        all.addAll(List.of(args));
        Cli c = Cli.run(all.toArray(String[]::new));
        assertEquals(0, c.code(), c.err());
        Files.writeString(dir.resolve("scenario.json"), scenarioJson);
    }

    /** The line of the per-property block that starts with {@code "  " + property + ": "}. */
    private static String line(String out, String property) {
        return out.lines().filter(l -> l.startsWith("  " + property + ": ")).findFirst()
                .orElseThrow(() -> new AssertionError(out));
    }

    /**
     * Stuck navigations: each run's stuck navigation misses its deadline, the others are discharged in time. The
     * block prints the deadline's Brier score against the base rate and its reliability rows, and the figures are
     * those of the runs' own forecasts, recomputed here (each run one unit of weight, each forecast against its own
     * obligation's outcome).
     */
    @Test
    @Timeout(300)
    void aDeadlinesForecastIsScoredPerObligationInTextJsonAndReport() throws Exception {
        Path report = tmp.resolve("report.html");
        Cli text = Cli.run("evaluate", "--logs", train.toString(), "--test", stuck.toString(), "--quiet", "--report",
                report.toString());
        assertEquals(0, text.code(), text.err());
        String out = text.out();
        assertTrue(out.contains("A deadline forecast is P(the pending obligation misses its deadline): its outcome "
                + "is whether that obligation missed it"), out);
        String nav = line(out, "navigation-in-time");
        assertTrue(nav.matches("  navigation-in-time: per obligation, 6 runs with forecasts, \\d+ forecasts, 4 with "
                + "an obligation that missed: Brier score \\d\\.\\d{3} \\(always saying the base rate: \\d\\.\\d{3}\\), "
                + "expected calibration error \\d\\.\\d{3} \\(a calibrated forecast shows up to \\d\\.\\d{3} on these "
                + "runs by chance, 9 times in 10\\)"), nav);
        List<String> lines = out.lines().toList();
        int at = lines.indexOf(nav);
        assertTrue(lines.get(at + 1).trim().startsWith("P in"), lines.get(at + 1));
        assertTrue(lines.get(at + 2).trim().matches("\\d\\.\\d - \\d\\.\\d +\\d+ +\\d+\\.\\d +\\d\\.\\d\\d +\\d\\.\\d\\d +"
                        + "\\d\\.\\d\\d-\\d\\.\\d\\d( +more than chance)?"),
                lines.get(at + 2));
        // the depleted training runs abort their navigation: the absence has an event forecast of its own, per run
        assertTrue(line(out, "no-abort").matches("  no-abort: per run, 6 runs with forecasts, \\d+ forecasts, \\d+ "
                + "violated: Brier score \\d\\.\\d{3} \\(always saying the base rate: \\d\\.\\d{3}\\).*"),
                line(out, "no-abort"));

        Cli json = Cli.run("evaluate", "--logs", train.toString(), "--test", stuck.toString(), "--quiet", "--json");
        JsonNode e = new ObjectMapper().readTree(json.out());
        JsonNode score = null;
        for (JsonNode p : e.get("properties")) {
            if (p.get("property").asText().equals("navigation-in-time")) {
                score = p;
            }
        }
        assertEquals("obligation", score.get("scope").asText());
        double brier = 0;
        double base = 0;
        int runs = 0;
        for (JsonNode r : e.get("runs")) {
            for (JsonNode p : r.get("properties")) {
                JsonNode f = p.get("forecasts");
                if (!p.get("property").asText().equals("navigation-in-time") || f.isNull()
                        || f.get("probabilities").isEmpty()) {
                    continue;
                }
                runs++;
                int n = f.get("probabilities").size();
                for (int i = 0; i < n; i++) {
                    double x = f.get("probabilities").get(i).asDouble();
                    int y = f.get("outcomes").get(i).asInt();
                    brier += (x - y) * (x - y) / n;
                    base += (f.get("baseRate").asDouble() - y) * (f.get("baseRate").asDouble() - y) / n;
                }
            }
        }
        assertEquals(6, runs);
        assertEquals(brier / runs, score.get("forecast").get("brier").asDouble(), 1e-9);
        assertEquals(base / runs, score.get("forecast").get("baseBrier").asDouble(), 1e-9);
        assertTrue(nav.contains(String.format(java.util.Locale.ROOT, "Brier score %.3f", brier / runs)), nav);

        String html = Files.readString(report);
        assertTrue(html.contains("<h3 id=property-forecasts>"), "the report's property section has the block");
        assertTrue(html.contains("<b>navigation-in-time</b>: per obligation, 6 runs with forecasts"), html);
    }

    /** On runs where every navigation arrived in time, the Brier score is said to show no skill. */
    @Test
    @Timeout(300)
    void withNothingViolatedTheBrierScoreClaimsNoSkill() {
        Cli c = Cli.run("evaluate", "--logs", train.toString(), "--test", train.toString(), "--quiet");
        assertEquals(0, c.code(), c.err());
        String nav = line(c.out(), "navigation-in-time");
        assertTrue(nav.contains(", 0 with an obligation that missed: "), nav);
        assertTrue(nav.endsWith("nothing was violated on these runs, so the Brier score cannot show skill (every run "
                + "held)"), nav);
    }

    /**
     * A faulty scenario whose runs abort the way to the charging station, learned against direct runs only: a recharge
     * with a blocked path leaves the direct model at the turn to the charger, before the abort. The matching's warning
     * names no-abort, in the event and to the hooks, and evaluate counts it in no-abort's row, not the battery's.
     */
    @Test
    @Timeout(300)
    void aFaultyScenariosWarningNamesThePropertyItViolates() throws Exception {
        Path logs = tmp.resolve("aborts");
        String faulty = "{\"faulty\": true, \"violates\": \"no-abort\"}";
        simulate(logs.resolve("direct"), "{\"faulty\": false}", "--scenario", "direct", "--runs", "6", "--seed", "501");
        simulate(logs.resolve("blocked"), faulty, "--scenario", "recharge", "--aborts", "1", "--abort-on", "station",
                "--runs", "6", "--seed", "501");
        Path test = tmp.resolve("aborts-test");
        simulate(test.resolve("blocked"), faulty, "--scenario", "recharge", "--aborts", "1", "--abort-on", "station",
                "--runs", "2", "--seed", "901");
        Path models = tmp.resolve("aborts-models");
        Cli learn = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString());
        assertEquals(0, learn.code(), learn.err());

        Path heard = tmp.resolve("heard.txt");
        Path log;
        try (var files = Files.list(test.resolve("blocked"))) {
            log = files.filter(p -> p.toString().endsWith(".log")).sorted().findFirst().orElseThrow();
        }
        Cli watch = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow", "--json",
                "--on-warning", "echo \"$PREDMON_PROPERTY\" >> " + heard);
        JsonNode warning = Cli.firstEvent(watch.jsonLines(), "warning").orElseThrow(() -> new AssertionError(
                watch.out()));
        assertEquals("matching", warning.get("clause").asText());
        assertEquals("blocked", warning.get("scenario").asText());
        assertEquals("no-abort", warning.get("property").asText());
        assertTrue(warning.get("reason").asText().startsWith("'navigation never aborts' (no-abort), which faulty "
                + "scenario blocked violates: the run can only be faulty scenario blocked"), warning.toString());
        JsonNode violation = Cli.firstEvent(watch.jsonLines(), "violation").orElseThrow();
        assertEquals("no-abort", violation.get("property").asText());
        assertTrue(warning.get("line").asLong() < violation.get("line").asLong(), "warned ahead of the abort");
        assertEquals(List.of("no-abort"), Files.readAllLines(heard));

        Cli eval = Cli.run("evaluate", "--logs", logs.toString(), "--test", test.toString(), "--quiet");
        assertEquals(0, eval.code(), eval.err());
        String row = eval.out().lines().filter(l -> l.startsWith("no-abort ")).findFirst()
                .orElseThrow(() -> new AssertionError(eval.out()));
        String[] cells = row.trim().split(" +");
        assertEquals(List.of("no-abort", "2", "0", "2", "2", "0"), List.of(cells).subList(0, 6),
                "runs, no evidence, violated, warned ahead, false alarms: " + row);
        String scenario = eval.out().lines().filter(l -> l.startsWith("blocked ")).findFirst().orElseThrow();
        assertEquals(List.of("blocked", "faulty", "2", "0"), List.of(scenario.trim().split(" +")).subList(0, 4),
                "runs, and no warning counted for the battery: " + scenario);
    }
}
