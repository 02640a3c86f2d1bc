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
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What {@code learn}'s cross-validation chose is what the saved models warn by. On the shipped sample logs the
 * battery's forecast rule warns the same 10 violations as the raw-value rule on the held-out folds with one false alarm
 * more, so the raw-value rule is chosen: {@code forecast.json} says {@code "rule": "baseline"} and every warning of the
 * battery in {@code watch} says it is the raw-value rule's. Every other property's model in the file agrees with its
 * scorecard's choice too.
 */
class ChosenRuleCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path tmp;

    @Test
    void theBaselineChosenOnTheFoldsIsTheRuleSavedAndWatched() throws Exception {
        Path models = tmp.resolve("models");
        Cli learned = Cli.run("learn", "--logs", "sample-logs", "--models", models.toString());
        assertEquals(0, learned.code(), learned.err());
        JsonNode forecast = JSON.readTree(Files.readString(models.resolve("forecast.json"))).get("properties")
                .get("battery");
        JsonNode card = forecast.get("scorecards").get(0);
        assertTrue(card.get("baselineChosen").asBoolean(), "the raw value does better on these folds: " + card);
        assertEquals("baseline", forecast.path("rule").asText(), "the headline's choice is saved");
        assertTrue(forecast.get("thresholdNote").asText().contains("the raw-value baseline warns"));

        List<String> checked = new ArrayList<>();
        JsonNode properties = JSON.readTree(Files.readString(models.resolve("forecast.json"))).get("properties");
        properties.fields().forEachRemaining(e -> {
            JsonNode cards = e.getValue().path("scorecards");
            if (!e.getKey().equals("battery") && cards.size() > 0) {
                assertEquals(cards.get(0).get("baselineChosen").asBoolean(),
                        "baseline".equals(e.getValue().path("rule").asText()), e.getKey());
                checked.add(e.getKey());
            }
        });
        assertEquals(List.of("no-abort"), checked, "the sample logs' absence is cross-validated too");

        Cli watched = Cli.run("watch", "--no-follow", "--json", "--log", "sample-logs/depleted/depleted-1.log",
                "--models", models.toString());
        int warnings = 0;
        for (String line : watched.out().lines().toList()) {
            JsonNode event = JSON.readTree(line);
            if ("warning".equals(event.path("event").asText()) && "battery".equals(event.path("property").asText())) {
                warnings++;
                assertEquals("novelty", event.get("clause").asText(), line);
                assertTrue(event.get("reason").asText().contains("(the raw-value rule, which did better than the "
                        + "forecast on the held-out folds)"), line);
                assertFalse(event.get("reason").asText().contains("reaching the warning threshold"), line);
            }
        }
        assertEquals(1, warnings, watched.out());
    }
}
