package dev.predmon.simulate;

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
        ObjectNode node = JSON.createObjectNode();
        node.put("faulty", scenario.faulty());
        node.put("description", scenario.id().toUpperCase(Locale.ROOT).charAt(0) + scenario.id().substring(1)
                + ": " + scenario.description());
        Files.writeString(dir.resolve("scenario.json"), JSON.writeValueAsString(node) + "\n");
    }
}
