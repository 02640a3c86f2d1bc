package dev.predmon.simulate;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes the JSON files that travel with simulated logs: the ground-truth sidecar {@code <log>.truth.json} and
 * the {@code scenario.json} of a directory of runs ({@code {"faulty": ..., "description": ...}}).
 */
public final class TruthWriter {

    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private TruthWriter() {
    }

    /** The sidecar path of a log: {@code run.log -> run.log.truth.json}. */
    public static Path sidecarOf(Path log) {
        return log.resolveSibling(log.getFileName() + ".truth.json");
    }

    /** The truth as JSON; the scenario is written by its command-line id ({@code depleted}). */
    public static String toJson(Truth truth) {
        ObjectNode node = JSON.valueToTree(truth);
        node.put("scenario", truth.scenario().id());
        if (truth.novelties() == null) {
            // A run without novelties keeps the sidecar it always had.
            node.remove("novelties");
        }
        try {
            return JSON.writeValueAsString(node);
        } catch (IOException e) {
            throw new IllegalStateException("cannot serialise the truth of seed " + truth.seed(), e);
        }
    }

    public static void writeTruth(Truth truth, Path file) throws IOException {
        Files.writeString(file, toJson(truth) + "\n");
    }

    /** Writes {@code dir/scenario.json} describing the runs of {@code scenario} in that directory. */
    public static void writeScenario(Scenario scenario, Path dir) throws IOException {
        Files.writeString(dir.resolve("scenario.json"), JSON.writeValueAsString(scenarioNode(scenario)) + "\n");
    }

    /**
     * Checks, before any run is written, that {@code dir} holds no {@code scenario.json} that says something else
     * than {@link #writeScenario} would write: a directory of runs of another scenario (or one the user described
     * differently) is not to be rewritten.
     *
     * @return a one-line reason to refuse, or null when the directory may take the runs
     */
    public static String otherScenario(Scenario scenario, Path dir) {
        Path file = dir.resolve("scenario.json");
        if (!Files.exists(file)) {
            return null;
        }
        JsonNode existing;
        try {
            existing = JSON.readTree(file.toFile());
        } catch (IOException e) {
            existing = null;
        }
        if (scenarioNode(scenario).equals(existing)) {
            return null;
        }
        String says = existing == null || !existing.isObject() ? "is not one simulate wrote"
                : "says faulty: " + existing.path("faulty") + ", " + existing.path("description");
        return file + ": " + says + ", not the " + scenario.id() + " scenario (faulty: " + scenario.faulty()
                + "); it is left as it is: choose another --out-dir";
    }

    private static ObjectNode scenarioNode(Scenario scenario) {
        ObjectNode node = JSON.createObjectNode();
        node.put("faulty", scenario.faulty());
        node.put("description", scenario.id().toUpperCase(Locale.ROOT).charAt(0) + scenario.id().substring(1)
                + ": " + scenario.description());
        return node;
    }
}
