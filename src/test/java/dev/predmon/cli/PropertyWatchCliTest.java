package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * watch checks every property of the abstraction on the run: each violation is an event naming its property, the
 * end summary gives every property's verdict, and the forecast property's verdict alone stays the run's
 * {@code violation}.
 */
class PropertyWatchCliTest {

    private static final Path ABORTS = Path.of("src/test/resources/property/navigation-aborts.txt");

    @TempDir
    Path tmp;

    @Test
    void anAbortIsAViolationOfNoAbortAndTheBatteryHolds() throws Exception {
        Path models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(tmp.resolve("logs"), models, "recharge");
        Cli r = Cli.run("watch", "--log", ABORTS.toString(), "--models", models.toString(), "--no-follow", "--json");
        ObjectMapper json = new ObjectMapper();
        List<JsonNode> violations = new ArrayList<>();
        JsonNode end = null;
        for (String line : r.out().lines().toList()) {
            JsonNode e = json.readTree(line);
            if (e.path("event").asText().equals("violation")) {
                violations.add(e);
            } else if (e.path("event").asText().equals("end")) {
                end = e;
            }
        }
        assertEquals(1, violations.size(), r.out());
        JsonNode v = violations.get(0);
        assertEquals("no-abort", v.get("property").asText());
        assertEquals("navigation never aborts", v.get("name").asText());
        assertEquals(157, v.get("line").asLong());
        assertEquals("GoTo/getStatus reply 3", v.get("what").asText());
        assertTrue(v.get("value").isNull() && v.get("battery").isNull(), v.toString());
        assertTrue(end != null, r.out());
        assertEquals(false, end.get("violation").asBoolean(), "the battery, the forecast's property, held");
        JsonNode properties = end.get("properties");
        assertEquals(5, properties.size());
        assertEquals("battery", properties.get(0).get("property").asText());
        assertEquals("holds", properties.get(0).get("verdict").asText());
        assertEquals("violated", properties.get(2).get("verdict").asText());
        assertEquals(157, properties.get(2).get("line").asLong());
        JsonNode nav = properties.get(3);
        assertEquals("navigation-in-time", nav.get("property").asText());
        assertEquals("pending", nav.get("verdict").asText());
        assertEquals(401, nav.get("deadline").asDouble());
        assertEquals("ticks", nav.get("unit").asText());
        // the models learned its training obligations: forecast whatever the rule (the match rule here), never warned
        assertEquals("deadline", nav.get("forecast").get("model").asText(), nav.toString());
        assertEquals("forecast", properties.get(0).get("forecast").get("model").asText());
        assertTrue(properties.get(0).get("forecast").get("probability").isNumber(), properties.toString());
        assertEquals(properties, end.get("runs").get(0).get("properties"));

        Cli text = Cli.run("watch", "--log", ABORTS.toString(), "--models", models.toString(), "--no-follow");
        assertEquals(r.code(), text.code());
        assertTrue(text.out().contains("line 157: VIOLATION of 'navigation never aborts' (no-abort): GoTo/getStatus"
                + " reply 3\n"), text.out());
        // each property's verdict with its latest forecast, or that it has none
        assertTrue(text.out().contains("\n  no-abort (navigation never aborts): violated at line 157: GoTo/getStatus"
                + " reply 3; no forecast: never violated in 2 training runs\n"), text.out());
        assertTrue(text.out().contains("\n  navigation-in-time (a navigation ends within 400 ticks): pending since line"
                + " 24 (tick 1 of the run, due by tick 401); no forecast: pending longer than any training obligation (no"
                + " evidence); 395 ticks left\n"), text.out());
        assertTrue(text.out().contains("\n  battery (battery level >= 20% (thesis 3.3.1)): holds; forecast: P(violation) "),
                text.out());
        // the run's outcome, worst first: the violated property, then the pending one and the one with no evidence
        // (no grasp was tried), then those that hold
        assertTrue(text.out().contains("; no-abort VIOLATED with no warning before it; navigation-in-time pending; "
                + "grasp-in-time no evidence; battery, charger-in-time hold"), "the run's outcome per property: "
                + text.out());
    }
}
