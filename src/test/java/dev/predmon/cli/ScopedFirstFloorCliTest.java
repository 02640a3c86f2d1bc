package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The headline property is an ordinary bound: given a scope, the battery's floor is judged, labelled in training and
 * told only in its scope, and the run's outcome says what its verdict says. The battery floor of 20 is checked "from a
 * goTo to the kitchen until a goTo to the charging station"; the depleted sample run goes below 20 on its way to the
 * charger only (after its last goTo, to the charging station, at line 2953), out of that scope.
 */
class ScopedFirstFloorCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path DEPLETED = Path.of("sample-logs", "depleted", "depleted-1.log");

    @TempDir
    Path tmp;

    @Test
    void aScopedBatteryFloorGivesOneVerdict() throws Exception {
        Cli shown = Cli.run("abstraction", "show", "thesis");
        assertEquals(0, shown.code(), shown.err());
        ObjectNode a = (ObjectNode) JSON.readTree(shown.out());
        a.put("name", "thesis-scoped-battery");
        ObjectNode battery = (ObjectNode) a.get("properties").get(0);
        assertEquals("battery", battery.get("id").asText());
        ObjectNode scope = battery.putObject("scope");
        scope.putObject("from").put("kind", "command").put("protocol", "GoTo").put("command", "goTo")
                .put("argument", "kitchen");
        scope.putObject("until").put("kind", "command").put("protocol", "GoTo").put("command", "goTo")
                .put("argument", "charging_station");
        Path abstraction = tmp.resolve("scoped-battery.json");
        Files.writeString(abstraction, a.toPrettyString());
        Path models = tmp.resolve("models");
        Cli learn = Cli.run("learn", "--logs", "sample-logs", "--abstraction", abstraction.toString(), "--models",
                models.toString());
        assertEquals(0, learn.code(), learn.err());

        Cli watched = Cli.run("watch", "--log", DEPLETED.toString(), "--models", models.toString(), "--no-follow",
                "--json");
        List<JsonNode> events = new ArrayList<>();
        for (String line : watched.out().lines().toList()) {
            events.add(JSON.readTree(line));
        }
        List<JsonNode> violations = events.stream().filter(e -> e.get("event").asText().equals("violation")
                && e.path("property").asText().equals("battery")).toList();
        assertEquals(List.of(), violations, "below 20 only on the way to the charger, out of the scope");
        JsonNode end = events.get(events.size() - 1);
        assertEquals("end", end.get("event").asText());
        JsonNode status = end.get("properties").get(0);
        assertEquals("battery", status.get("property").asText());
        assertEquals("holds", status.get("verdict").asText());
        assertEquals(false, end.get("violation").asBoolean(), "the outcome says what the battery's verdict says");
        assertTrue(List.of(0, 1, 5).contains(watched.code()), "no violation: " + watched.code() + " " + watched.err());

        // learn labelled the runs by the same verdict: the depleted runs are not counted as violating the battery
        JsonNode forecast = JSON.readTree(models.resolve("forecast.json").toFile()).get("properties").get("battery");
        Cli unscopedLearn = Cli.run("learn", "--logs", "sample-logs", "--models", tmp.resolve("plain").toString());
        assertEquals(0, unscopedLearn.code(), unscopedLearn.err());
        JsonNode plain = JSON.readTree(tmp.resolve("plain").resolve("forecast.json").toFile()).get("properties")
                .get("battery");
        assertTrue(forecast.get("violating").asInt() < plain.get("violating").asInt(),
                "scoped " + forecast.get("violating") + ", whole run " + plain.get("violating"));
    }
}
