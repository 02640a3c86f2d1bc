package dev.predmon.live;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.event.LogEvent;
import dev.predmon.forecast.Forecast;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.parse.Clock;
import dev.predmon.support.Records;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code /metrics}: per log and property, what the tile shows and what happened, in the Prometheus text format. */
class MetricsTest {

    private static final Abstraction A = AbstractionFiles.defaults();
    private static final String PROPERTY = A.safety().orElseThrow().name();
    private static ModelSet models;
    private final AtomicLong now = new AtomicLong(1_000_000);

    @BeforeAll
    static void shippedModels() throws Exception {
        models = ModelStore.read(Path.of("models"), A);
    }

    private Board board() {
        return new Board(models.models(), A.safety(), Duration.ofSeconds(10), now::get);
    }

    /** Every sample of the scrape: {@code name{labels}} as written, to its value. */
    private static Map<String, Double> samples(Board b) {
        String text = new String(b.metrics().scrape(), StandardCharsets.UTF_8);
        Map<String, Double> samples = new LinkedHashMap<>();
        for (String line : text.split("\n", -1)) {
            if (!line.isEmpty() && !line.startsWith("#")) {
                int space = line.lastIndexOf(' ');
                samples.put(line.substring(0, space), Double.parseDouble(line.substring(space + 1)));
            }
        }
        return samples;
    }

    private static String series(String name, String log, String robot, String... more) {
        StringBuilder b = new StringBuilder(name).append("{log=\"").append(log).append("\",property=\"")
                .append(PROPERTY).append("\",robot=\"").append(robot).append('"');
        for (int i = 0; i < more.length; i += 2) {
            b.append(',').append(more[i]).append("=\"").append(more[i + 1]).append('"');
        }
        return b.append('}').toString();
    }

    private static Forecast forecast(double p, double ttv, String unit) {
        return new Forecast(p, ttv, ttv * 0.8, ttv * 1.5, Forecast.Basis.MATCHED, null, 20, 8, 40.0, -0.9, unit);
    }

    private static final java.util.regex.Pattern LOG_LABEL = java.util.regex.Pattern.compile("log=\"([^\"]*)\"");
    private static final java.util.regex.Pattern ROBOT_LABEL = java.util.regex.Pattern.compile("robot=\"([^\"]*)\"");

    /** Each log's {@code robot} labels over every series of the scrape. */
    private static Map<String, java.util.Set<String>> robotsByLog(Map<String, Double> samples) {
        Map<String, java.util.Set<String>> robots = new java.util.TreeMap<>();
        for (String series : samples.keySet()) {
            java.util.regex.Matcher log = LOG_LABEL.matcher(series);
            java.util.regex.Matcher robot = ROBOT_LABEL.matcher(series);
            assertTrue(log.find() && robot.find(), series);
            robots.computeIfAbsent(log.group(1), l -> new java.util.TreeSet<>()).add(robot.group(1));
        }
        return robots;
    }

    /** The {@code robot} labels of the series named {@code name} whose value passes {@code test}. */
    private static java.util.Set<String> robots(Map<String, Double> samples, String name, String match,
                                                java.util.function.DoublePredicate test) {
        java.util.Set<String> robots = new java.util.TreeSet<>();
        samples.forEach((series, value) -> {
            java.util.regex.Matcher robot = ROBOT_LABEL.matcher(series);
            if (series.startsWith(name + "{") && series.contains(match) && test.test(value) && robot.find()) {
                robots.add(robot.group(1));
            }
        });
        return robots;
    }

    /**
     * Logs whose names share a beginning: the page shows them short ({@code grasp}, {@code nav}), but every series
     * labels a log's robot with its whole name, from the first scrape on and after a third log appears (which changes
     * the short names), so that {@code predmon_state{state="violation"} == 1 and on(robot)
     * predmon_violations_total > 0} finds the violated robot.
     */
    @Test
    void theRobotLabelIsTheWholeNameOnEverySeriesAndStaysWhenALogAppears() {
        Board b = new Board(models.models(), A.safety(), A.properties(), Duration.ofSeconds(10), now::get,
                RobotNames.byFile(), List.of());
        b.tile("robots/r1-grasp.log");
        b.tile("robots/r1-nav.log");
        Map<String, java.util.Set<String>> first = robotsByLog(samples(b));
        assertEquals(Map.of("robots/r1-grasp.log", java.util.Set.of("r1-grasp"), "robots/r1-nav.log",
                java.util.Set.of("r1-nav")), first);
        b.tile("robots/r1-success-earlier.log");
        Tile grasp = b.tile("robots/r1-grasp.log");
        b.event(grasp, LogEvent.of("robots/r1-grasp.log", new MonitorEvent.Violation(34.6, 8219, PROPERTY, 15.86,
                20.85, Clock.SECONDS, 0)));
        Map<String, Double> s = samples(b);
        assertEquals(Map.of("robots/r1-grasp.log", java.util.Set.of("r1-grasp"), "robots/r1-nav.log",
                java.util.Set.of("r1-nav"), "robots/r1-success-earlier.log", java.util.Set.of("r1-success-earlier")),
                robotsByLog(s), "one label a log, the same as before the third log came");
        java.util.Set<String> violatedNow = robots(s, "predmon_state", "state=\"violation\"", v -> v == 1);
        java.util.Set<String> counted = robots(s, "predmon_violations_total", "", v -> v > 0);
        assertEquals(java.util.Set.of("r1-grasp"), violatedNow);
        assertEquals(violatedNow, counted, "the join on(robot) of the state and the counter");
    }

    /**
     * A deleted log's tile says so, with when it leaves; {@link Board#DELETED_KEPT} later it has left the page and
     * every one of its series has left {@code /metrics}. A log that comes back gets its tile back.
     */
    @Test
    void aDeletedLogsTileSaysSoAndLeavesWithItsSeries(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Board b = board();
        Path gone = java.nio.file.Files.writeString(dir.resolve("r1.log"), "x");
        Path kept = java.nio.file.Files.writeString(dir.resolve("r2.log"), "x");
        for (Path p : List.of(gone, kept)) {
            Tile t = b.tile(p.toString());
            Judged.record(t, new Records().at(1).level(80).list().get(1));
            b.event(t, LogEvent.of(p.toString(), new MonitorEvent.Violation(34.6, 8219, PROPERTY, 15.86, 20.85,
                    Clock.SECONDS, 0)));
        }
        java.nio.file.Files.delete(gone);
        b.status(null);
        now.addAndGet(60_000);
        com.fasterxml.jackson.databind.JsonNode tile = b.status(gone.toString()).get("logs").get(0);
        assertEquals(60.0, tile.get("deleted").asDouble(), "deleted a minute ago: " + tile);
        assertEquals(Board.DELETED_KEPT.toSeconds() - 60.0, tile.get("leavesIn").asDouble());
        assertFalse(b.status(kept.toString()).get("logs").get(0).has("deleted"));
        assertTrue(samples(b).keySet().stream().anyMatch(k -> k.contains(gone.toString())), "still there");

        now.addAndGet(Board.DELETED_KEPT.toMillis());
        com.fasterxml.jackson.databind.JsonNode logs = b.status(null).get("logs");
        assertEquals(1, logs.size(), "the deleted log's tile has left");
        assertEquals(kept.toString(), logs.get(0).get("log").asText());
        Map<String, Double> s = samples(b);
        assertTrue(s.keySet().stream().noneMatch(k -> k.contains(gone.toString())), s.keySet().toString());
        assertEquals(1.0, s.get(series("predmon_violations_total", kept.toString(), "r2")), s.toString().replaceAll("predmon_property[^,]*, ", ""));

        java.nio.file.Files.writeString(gone, "x");
        Tile back = b.tile(gone.toString());
        b.grew(back);
        assertEquals(2, b.status(null).get("logs").size(), "a log written again is shown again");
    }

    @Test
    void aNewLogHasItsStateAndCountersAtZeroButNoMadeUpForecastOrValue() {
        Board b = board();
        b.tile("robots/r1.log");
        Map<String, Double> s = samples(b);
        assertEquals(0.0, s.get(series("predmon_warnings_total", "robots/r1.log", "r1")), s.toString());
        assertEquals(0.0, s.get(series("predmon_violations_total", "robots/r1.log", "r1")));
        assertEquals(1.0, s.get(series("predmon_state", "robots/r1.log", "r1", "state", "waiting")));
        for (String other : List.of("violation", "warning", "unknown", "ok", "ended")) {
            assertEquals(0.0, s.get(series("predmon_state", "robots/r1.log", "r1", "state", other)), other);
        }
        assertTrue(s.keySet().stream().noneMatch(k -> k.startsWith("predmon_violation_probability")
                || k.startsWith("predmon_value") || k.startsWith("predmon_time_to_violation")), s.toString());
    }

    @Test
    void probabilityTimeValueStateAndCountsFollowTheRunsOfALog() {
        Board b = board();
        Tile t = b.tile("robots/r1.log");
        b.tile("robots/r2.log");
        Judged.record(t, new Records().at(1).level(80).list().get(1));
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.ForecastChanged(1, 10, forecast(0.42, 75.5, "s"), Clock.SECONDS, 0)));
        Map<String, Double> s = samples(b);
        assertEquals(0.42, s.get(series("predmon_violation_probability", "robots/r1.log", "r1")));
        assertEquals(75.5, s.get(series("predmon_time_to_violation_seconds", "robots/r1.log", "r1")));
        assertEquals(80.0, s.get(series("predmon_value", "robots/r1.log", "r1")));
        assertEquals(1.0, s.get(series("predmon_state", "robots/r1.log", "r1", "state", "ok")));
        assertFalse(s.containsKey(series("predmon_violation_probability", "robots/r2.log", "r2")), "no forecast yet");

        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Warning(30, 70, List.of("depleted"), 27.8, 14, Clock.SECONDS, 0)));
        Judged.record(t, new Records().at(35).level(18).list().get(1));
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Violation(35, 90, PROPERTY, 18.0, 21.0, Clock.SECONDS, 0)));
        s = samples(b);
        assertEquals(1.0, s.get(series("predmon_state", "robots/r1.log", "r1", "state", "violation")));
        assertEquals(0.0, s.get(series("predmon_state", "robots/r1.log", "r1", "state", "ok")));
        assertEquals(18.0, s.get(series("predmon_value", "robots/r1.log", "r1")));

        // a second run warns again: the counters go on across runs, the state starts over
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.RunStarted(1, 100, 500, Clock.SECONDS)));
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Warning(530, 170, List.of("depleted"), 30.1, 14, Clock.SECONDS, 1)));
        s = samples(b);
        assertEquals(2.0, s.get(series("predmon_warnings_total", "robots/r1.log", "r1")));
        assertEquals(1.0, s.get(series("predmon_violations_total", "robots/r1.log", "r1")));
        assertEquals(1.0, s.get(series("predmon_state", "robots/r1.log", "r1", "state", "warning")));
        assertEquals(0.0, s.get(series("predmon_warnings_total", "robots/r2.log", "r2")), "other logs untouched");

        // a log that stops growing mid-run is stale
        now.addAndGet(11_000);
        assertEquals(1.0, samples(b).get(series("predmon_stale", "robots/r1.log", "r1")));
    }

    /** A log counted in ticks gets its time to the violation in ticks, under a name that says so. */
    @Test
    void aLogCountedInTicksHasItsTimeInTicks() {
        Board b = board();
        Tile t = b.tile("console.txt");
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.ForecastChanged(3, 10, forecast(0.3, 412, "ticks"), Clock.TICKS, 0)));
        Map<String, Double> s = samples(b);
        assertEquals(412.0, s.get(series("predmon_time_to_violation_ticks", "console.txt", "console")));
        assertFalse(s.keySet().stream().anyMatch(k -> k.startsWith("predmon_time_to_violation_seconds{")));
    }

    /** An abstraction without a property: the state and the counters, the property empty (to Prometheus: none). */
    @Test
    void withoutAPropertyTheLogStillHasItsState() {
        Board b = new Board(models.models(), Optional.empty(), Duration.ofSeconds(10), now::get);
        b.tile("r.log");
        String text = new String(b.metrics().scrape(), StandardCharsets.UTF_8);
        assertTrue(text.contains("predmon_state{log=\"r.log\",property=\"\",robot=\"r\",state=\"waiting\"} 1.0"), text);
        assertTrue(text.contains("predmon_warnings_total{log=\"r.log\",property=\"\",robot=\"r\"} 0.0"), text);
    }

    /** Label values are escaped as the format says, so that no log name can forge a sample. */
    @Test
    void aHostileLogNameStaysInsideItsLabel() {
        Board b = board();
        b.tile("a\"b\\c\nd.log");
        String text = new String(b.metrics().scrape(), StandardCharsets.UTF_8);
        assertTrue(text.contains("log=\"a\\\"b\\\\c\\nd.log\""), text);
        for (String line : text.split("\n", -1)) {
            assertTrue(line.isEmpty() || line.startsWith("# ") || line.startsWith("predmon_"), line);
        }
    }

    /** Over HTTP: the content type Prometheus expects and one line of HELP per metric. */
    @Test
    void theServerAnswersMetricsInTheTextFormat() throws Exception {
        Board b = board();
        Tile t = b.tile("r.log");
        Judged.record(t, new Records().at(1).level(80).list().get(1));
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.ForecastChanged(1, 10, forecast(0.42, 75.5, "s"), Clock.SECONDS, 0)));
        try (LiveServer server = LiveServer.start(HttpAddress.parse("0"), b)) {
            URI url = server.url().resolve("/metrics");
            HttpResponse<String> r = HttpClient.newHttpClient().send(HttpRequest.newBuilder(url).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertEquals(200, r.statusCode());
            assertEquals("text/plain; version=0.0.4; charset=utf-8", r.headers().firstValue("Content-Type").orElse(""));
            for (String name : List.of("predmon_state", "predmon_stale", "predmon_violation_probability",
                    "predmon_time_to_violation_seconds", "predmon_value",
                    "predmon_warnings_total", "predmon_violations_total")) {
                assertTrue(r.body().contains("# HELP " + name + " "), name + " in " + r.body());
            }
        }
    }
}
