package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.net.URI;
import java.net.URLEncoder;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code /status} with the forecast, as a script reads it from {@code watch --http}: each log's {@code forecast} is the
 * object {@code watch --json} prints (the same fields), beside the robot's name, its state, the warning's reason and
 * the property's recommended action; and the naming options' errors.
 */
class LiveForecastStatusTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private final HttpClient http = HttpClient.newHttpClient();

    @TempDir
    Path dir;

    private JsonNode status(URI url, String log) throws Exception {
        String q = "/status?log=" + URLEncoder.encode(log, StandardCharsets.UTF_8);
        return JSON.readTree(http.send(HttpRequest.newBuilder(url.resolve(q)).build(),
                HttpResponse.BodyHandlers.ofString()).body()).get("logs").get(0);
    }

    /**
     * The last event of a kind about the battery that {@code watch --json} printed so far, or null: the tile's
     * headline is the battery's (the first floor), not the other properties' (no-abort's, a deadline's).
     */
    private static JsonNode last(Cli.Running w, String kind) throws Exception {
        JsonNode found = null;
        for (String line : w.out().toString().split("\n", 0)) {
            if (line.startsWith("{")) {
                JsonNode e = JSON.readTree(line);
                if (e.get("event").asText().equals(kind) && e.get("property").asText().equals("battery")) {
                    found = e;
                }
            }
        }
        return found;
    }

    @Test
    @Timeout(120)
    void statusHasEachLogsForecastAsWatchJsonPrintsItWithTheReasonAndTheAction() throws Exception {
        Path log = dir.resolve("monitor.log");
        Files.writeString(log, FleetWatchTest.run(Scenario.DEPLETED, 9001));
        Cli.Running w = Cli.start("watch", "--log", log.toString(), "--models", ForecastModels.get().toString(),
                "--json", "--http", "0", "--name", "R1 kitchen", "--stale-after", "600");
        try {
            URI url = LiveViewTest.url(w);
            FleetWatchTest.await(() -> w.out().toString().contains("\"event\":\"violation\""), "the violation");
            List<String> seen = new ArrayList<>();
            long deadline = System.nanoTime() + 20_000_000_000L;
            JsonNode tile;
            JsonNode printed;
            do {
                tile = status(url, log.toString());
                printed = last(w, "forecast");
                seen.add(String.valueOf(tile.get("forecast")));
                assertTrue(System.nanoTime() < deadline, "the forecast never matched the last printed: " + seen);
            } while (printed == null || !printed.get("forecast").equals(tile.get("forecast")));
            List<String> fields = new ArrayList<>();
            tile.get("forecast").fieldNames().forEachRemaining(fields::add);
            List<String> printedFields = new ArrayList<>();
            printed.get("forecast").fieldNames().forEachRemaining(printedFields::add);
            assertEquals(printedFields, fields, "the same fields as watch --json");
            assertTrue(fields.containsAll(List.of("probability", "timeToViolation", "basis", "novelSince", "runs",
                    "violated", "explanation")), fields.toString());

            assertEquals("R1 kitchen", tile.get("name").asText());
            assertEquals("violation", tile.get("state").asText());
            assertEquals("send the robot to the charging station", tile.get("action").asText(),
                    "the built-in abstraction's action, through the models' abstraction.json");
            JsonNode warning = last(w, "warning");
            assertNotNull(warning);
            assertEquals(warning.get("reason").asText(), tile.get("warning").get("reason").asText());
            assertEquals(warning.get("forecast"), tile.get("warning").get("forecast"));
            assertTrue(tile.get("warning").get("reason").asText().contains("P(violation)"), tile.toString());
        } finally {
            w.stop();
        }
    }

    @Test
    void theRobotsNamesAreForTheLiveViewAndNameOneLogEach() throws Exception {
        Path a = Files.writeString(dir.resolve("a.log"), "");
        Path b = Files.writeString(dir.resolve("b.log"), "");
        String models = Path.of("models").toString();
        Cli several = Cli.run("watch", "--log", a.toString(), "--log", b.toString(), "--models", models,
                "--http", "0", "--name", "R1");
        assertEquals(ExitCodes.USAGE, several.code(), several.err());
        assertTrue(several.err().contains("--name-pattern"), several.err());
        Cli noHttp = Cli.run("watch", "--log", a.toString(), "--models", models, "--name", "R1");
        assertEquals(ExitCodes.USAGE, noHttp.code(), noHttp.err());
        assertTrue(noHttp.err().contains("--http"), noHttp.err());
        Cli badPattern = Cli.run("watch", "--log", dir.toString(), "--models", models, "--http", "0",
                "--name-pattern", "{robot}");
        assertEquals(ExitCodes.USAGE, badPattern.code(), badPattern.err());
        assertTrue(badPattern.err().contains("unknown placeholder {robot}"), badPattern.err());
    }
}
