package dev.predmon.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Model directories that cannot be trusted, read by a command that judges a log: an index and DOT files that
 * contradict each other, an index with no model, and JSON far deeper or larger than any predmon file. Each is
 * exit 3 with one line naming the file and what is wrong, never a verdict about the robot and never an internal
 * error. {@link ModelPartsCliTest} has the forecast's file and the learn id that ties the parts together.
 */
class ModelFilesCliTest {

    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
    private static final Path LOG = Path.of("sample-logs", "direct", "direct-1.log");

    @TempDir
    Path tmp;
    Path models;

    /** A copy of the shipped models, to be broken one way per test. */
    @BeforeEach
    void copyShippedModels() throws IOException {
        models = copyOfShippedModels(tmp);
    }

    /** A copy of the shipped models in {@code tmp}/models. */
    static Path copyOfShippedModels(Path tmp) throws IOException {
        Path models = Files.createDirectories(tmp.resolve("models"));
        try (Stream<Path> s = Files.list(Path.of("models"))) {
            for (Path p : s.toList()) {
                Files.copy(p, models.resolve(p.getFileName()));
            }
        }
        return models;
    }

    /** classify of a nominal run: exit 3 and one line naming {@code file} (and its line) and saying {@code what}. */
    private void refused(Path file, String what) {
        refused(models, file, what);
    }

    /** As above, for the models in {@code models}; the line is returned. */
    static String refused(Path models, Path file, String what) {
        Cli r = Cli.run("classify", "--models", models.toString(), "--log", LOG.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
        List<String> lines = r.err().strip().lines().toList();
        assertEquals(1, lines.size(), r.err());
        assertTrue(lines.get(0).startsWith("predmon: " + file + ":") && lines.get(0).contains(what), r.err());
        assertEquals("", r.out(), "no verdict");
        return lines.get(0);
    }

    private ObjectNode index() throws IOException {
        return (ObjectNode) JSON.readTree(models.resolve("index.json").toFile());
    }

    private void write(ObjectNode index) throws IOException {
        Files.writeString(models.resolve("index.json"), JSON.writeValueAsString(index));
    }

    @Test
    void theShippedCopyIsAccepted() {
        Cli r = Cli.run("classify", "--models", models.toString(), "--log", LOG.toString());
        assertEquals(ExitCodes.OK, r.code(), r.err());
    }

    /** direct.dot replaced by another learn's machine: it has 18 states where the index says 7. */
    @Test
    void aDotFileWithOtherStatesThanTheIndexSays() throws IOException {
        Files.copy(models.resolve("depleted.dot"), models.resolve("direct.dot"),
                StandardCopyOption.REPLACE_EXISTING);
        refused(models.resolve("direct.dot"), "has 18 states, but index.json says 7");
    }

    @Test
    void aDotFileWithAnOutputOutsideTheAbstraction() throws IOException {
        Path dot = models.resolve("direct.dot");
        Files.writeString(dot, Files.readString(dot).replace("o_level_high", "o_level_over_9000"));
        refused(dot, "output 'o_level_over_9000' (after input 'Delta') is not one of the abstraction's outputs");
    }

    @Test
    void aScenarioListedTwice() throws IOException {
        ObjectNode index = index();
        ((ObjectNode) index.withArray("scenarios").get(2)).put("name", "direct");
        write(index);
        refused(models.resolve("index.json"), "scenario 'direct' is listed twice");
    }

    /** The forecast is read from the one file learn writes, never from a file the index points elsewhere. */
    @Test
    void aForecastThatIsNotTheFileLearnWrites() throws IOException {
        Files.writeString(tmp.resolve("elsewhere.json"), "{}");
        ObjectNode index = index();
        index.put("forecast", "../elsewhere.json");
        write(index);
        refused(models.resolve("index.json"), "forecast '../elsewhere.json' is not forecast.json");
    }

    /** Without a model every run would be "no model matches" (exit 5): a verdict that means nothing. */
    @Test
    void anIndexWithoutScenariosHasNoModels() throws IOException {
        ObjectNode index = index();
        index.putArray("scenarios");
        write(index);
        refused(models.resolve("index.json"), "no models");
    }

    @Test
    void anIndexNestedAHundredThousandLevelsDeep() throws IOException {
        Files.writeString(models.resolve("index.json"),
                "{\"format\": 1, \"x\": " + "[".repeat(100_000) + "]".repeat(100_000) + "}");
        refused(models.resolve("index.json"), "not a predmon model index: nested more than 64 levels deep");
    }

    @Test
    void anIndexHoldingA30MegabyteString() throws IOException {
        Files.writeString(models.resolve("index.json"), "{\"format\": 1, \"x\": \"" + "a".repeat(30_000_000) + "\"}");
        refused(models.resolve("index.json"), "not a predmon model index: a string longer than 1000000 characters");
    }

    /** An abstraction file as deep: the same line, in words, without the JSON library's class names. */
    @Test
    void anAbstractionFileNestedTooDeep() throws IOException {
        Path file = Files.writeString(tmp.resolve("deep.json"),
                "{\"name\": \"x\", \"rules\": " + "[".repeat(100_000) + "]".repeat(100_000) + "}");
        Cli r = Cli.run("classify", "--abstraction", file.toString(), "--models", models.toString(),
                "--log", LOG.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.err());
        assertTrue(r.err().startsWith("predmon: " + file + ":1:") && r.err().contains("nested more than 64 levels deep"),
                r.err());
        assertFalse(r.err().contains("StreamReadConstraints"), r.err());
    }
}
