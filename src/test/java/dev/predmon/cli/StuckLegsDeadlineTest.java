package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Stuck navigations never in training: learned on the shipped sample logs (simulated runs of every scenario, ten each,
 * none with a stuck navigation), watched on runs of other seeds whose navigation never arrives, on the short leg (the way to the charging station of a
 * recharge run) and on the long one (the way to the kitchen of a direct run), with a stuck length drawn per run, and on
 * safe runs. The deadline (400 ticks) is warned before it passes in at least 90% of the violating runs, with no false
 * alarm, and its median lead is at least that of the elapsed-time rule, which warns once a navigation is pending longer
 * than every navigation of the training runs took. On the short legs the lead is longer than that rule's: a leg that
 * usually takes a few ticks is late long before the longest leg of all.
 */
class StuckLegsDeadlineTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String ID = "navigation-in-time";
    private static final int RUNS = 5;

    @TempDir
    Path tmp;

    @Test
    void stuckLegsAreWarnedAheadWithNoFalseAlarmAndALeadAtLeastTheElapsedTimeRules() throws Exception {
        Path models = tmp.resolve("models");
        Cli learned = Cli.run("learn", "--logs", "sample-logs", "--models", models.toString());
        assertEquals(0, learned.code(), learned.err());
        JsonNode obligations = JSON.readTree(Files.readString(models.resolve("forecast.json")))
                .get("properties").get(ID);
        double longest = 0;
        for (JsonNode d : obligations.get("discharged")) {
            longest = Math.max(longest, d.asDouble());
        }
        // the elapsed-time rule warns at the first tick past every training navigation (the longest that arrived; a
        // censored one, whose run ended on the way, would only put it later)
        double ruleLead = 400 - (Math.floor(longest) + 1);

        List<Double> shortLeads = new ArrayList<>();
        List<Double> longLeads = new ArrayList<>();
        int violating = 0;
        int warned = 0;
        for (int i = 0; i < RUNS; i++) {
            for (boolean shortLeg : List.of(true, false)) {
                Path log = shortLeg
                        ? BoundForecastCliTest.simulate(tmp, "recharge", String.valueOf(9100 + i), "--never-arrives",
                        "420..520", "--abort-on", "station", "--out", tmp.resolve("short-" + i + ".log").toString())
                        : BoundForecastCliTest.simulate(tmp, "direct", String.valueOf(9200 + i), "--never-arrives",
                        "420..520", "--out", tmp.resolve("long-" + i + ".log").toString());
                log = tmp.resolve((shortLeg ? "short-" : "long-") + i + ".log");
                JsonNode truth = JSON.readTree(Files.readString(Path.of(log + ".truth.json")));
                assertTrue(truth.get("properties").get(ID).get("violated").asBoolean(), log.toString());
                violating++;
                List<JsonNode> events = watch(log, models);
                JsonNode warning = first(events, "warning");
                JsonNode violation = first(events, "violation");
                assertNotNull(violation, "the deadline passes in " + log);
                if (warning != null && warning.get("line").asLong() < violation.get("line").asLong()) {
                    warned++;
                    double lead = warning.get("deadline").get("timeLeft").asDouble();
                    (shortLeg ? shortLeads : longLeads).add(lead);
                }
            }
        }
        int alarms = 0;
        for (int i = 0; i < RUNS; i++) {
            for (String s : List.of("recharge", "direct")) {
                Path log = BoundForecastCliTest.simulate(tmp, s, String.valueOf(9300 + i));
                alarms += first(watch(log, models), "warning") == null ? 0 : 1;
            }
        }
        List<Double> all = new ArrayList<>(shortLeads);
        all.addAll(longLeads);
        System.out.printf("stuck legs: warned %d of %d ahead, %d false alarm(s) in %d safe runs; median lead %s ticks"
                        + " (short legs %s, long legs %s), the elapsed-time rule's %s%n", warned, violating, alarms,
                2 * RUNS, median(all), median(shortLeads), median(longLeads), ruleLead);
        assertTrue(warned >= 0.9 * violating, warned + " of " + violating + " warned ahead");
        assertEquals(0, alarms, "false alarms in safe runs");
        assertTrue(median(all) >= ruleLead, median(all) + " against " + ruleLead);
        assertTrue(median(shortLeads) > ruleLead, "a short leg is late early: " + shortLeads + " vs " + ruleLead);
        assertTrue(median(longLeads) >= ruleLead, longLeads + " vs " + ruleLead);
    }

    private static List<JsonNode> watch(Path log, Path models) throws Exception {
        Cli r = Cli.run("watch", "--no-follow", "--json", "--log", log.toString(), "--models", models.toString());
        List<JsonNode> events = new ArrayList<>();
        for (String line : r.out().lines().filter(l -> !l.isBlank()).toList()) {
            events.add(JSON.readTree(line));
        }
        return events;
    }

    private static JsonNode first(List<JsonNode> events, String event) {
        return events.stream().filter(e -> e.path("event").asText().equals(event)
                && e.path("property").asText().equals(ID)).findFirst().orElse(null);
    }

    private static double median(List<Double> xs) {
        if (xs.isEmpty()) {
            return Double.NaN;
        }
        List<Double> s = xs.stream().sorted().toList();
        int n = s.size();
        return n % 2 == 1 ? s.get(n / 2) : (s.get(n / 2 - 1) + s.get(n / 2)) / 2;
    }
}
