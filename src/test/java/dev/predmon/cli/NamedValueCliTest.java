package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.InputStream;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A hand-written abstraction whose bound property is not called battery: {@code watch}'s text names the value by the
 * property's id from the file, and its JSON carries it as {@code value} (with {@code battery}, the older name, beside
 * it).
 */
class NamedValueCliTest {

    @TempDir
    Path tmp;

    @Test
    @Timeout(300)
    void watchNamesTheValueAfterTheFilesProperty() throws Exception {
        ObjectMapper json = new ObjectMapper();
        ObjectNode root;
        try (InputStream in = Abstraction.class.getResourceAsStream("default-abstraction.json")) {
            root = (ObjectNode) json.readTree(in);
        }
        root.put("name", "energy reserve");
        ObjectNode floor = (ObjectNode) root.get("properties").get(0).deepCopy();
        floor.put("id", "reserve");
        floor.put("name", "energy reserve >= 20%");
        ArrayNode only = root.putArray("properties");
        only.add(floor);
        Path abstraction = tmp.resolve("reserve.json");
        json.writeValue(abstraction.toFile(), root);

        Path models = tmp.resolve("models");
        Cli learned = Cli.run("learn", "--logs", "sample-logs", "--abstraction", abstraction.toString(), "--models",
                models.toString());
        assertEquals(ExitCodes.OK, learned.code(), learned.err());
        Path log = tmp.resolve("depleted.log");
        Cli simulated = Cli.run("simulate", "--out", log.toString(), "--scenario", "depleted", "--seed", "424242");
        assertEquals(ExitCodes.OK, simulated.code(), simulated.err());

        Cli text = Cli.run("watch", "--no-follow", "--log", log.toString(), "--models", models.toString());
        List<String> lines = text.out().lines().filter(l -> l.contains("WARNING") || l.contains("VIOLATION"))
                .toList();
        assertEquals(2, lines.size(), text.out());
        assertTrue(lines.get(0).matches(".*WARNING: .*; reserve \\d+\\.\\d\\d"), lines.get(0));
        assertTrue(lines.get(1).matches(".*VIOLATION of 'energy reserve >= 20%': \\d+\\.\\d\\d; lead of the warning: "
                + ".*, reserve \\d+\\.\\d\\d at the warning vs \\d+\\.\\d\\d now"), lines.get(1));
        lines.forEach(l -> assertFalse(l.contains("battery"), l));

        List<JsonNode> events = Cli.run("watch", "--no-follow", "--json", "--log", log.toString(), "--models",
                models.toString()).jsonLines();
        JsonNode warning = Cli.firstEvent(events, "warning").orElseThrow();
        assertEquals("reserve", warning.get("property").asText());
        assertTrue(warning.get("value").isNumber(), warning.toString());
        assertEquals(warning.get("value"), warning.get("battery"));
    }
}
