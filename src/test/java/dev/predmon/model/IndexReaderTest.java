package dev.predmon.model;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import dev.predmon.BadInputException;
import dev.predmon.abstraction.file.AbstractionFiles;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

/**
 * {@link IndexReader} reads {@code index.json} as the {@code ObjectMapper} that read it before did: the same
 * {@link ModelIndex} from what {@code learn} writes, the same messages for a missing file and for text that is
 * not JSON, and one line naming the place for a value of the wrong type.
 */
class IndexReaderTest {

    /** How {@link ModelStore} read the index before. */
    private static final ObjectMapper BEFORE = new ObjectMapper()
            .enable(SerializationFeature.INDENT_OUTPUT)
            .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES);

    @TempDir
    Path tmp;

    @Test
    void readsTheShippedIndexAsTheMapperDid() throws Exception {
        Path file = Path.of("models", "index.json");
        assertEquals(BEFORE.readValue(file.toFile(), ModelIndex.class), IndexReader.read(file));
    }

    @Test
    void readsEveryFieldAsTheMapperDid() throws Exception {
        var definition = JsonNodeFactory.instance.objectNode().put("name", "n").put("x", 1.5);
        ModelIndex index = new ModelIndex(1, new ModelIndex.AbstractionInfo("n", "ab12", definition,
                Map.of("level_i", 0.75, "a_i", 2.0)), List.of("Delta", "a_i"),
                List.of(new ModelIndex.Scenario("s", true, null, 3, List.of(
                        new ModelIndex.Model("s-1.dot", 4, 2, List.of("a.log", "b.log")),
                        new ModelIndex.Model("s-2.dot", 1, 1, List.of())))));
        Path file = Files.writeString(tmp.resolve("index.json"), BEFORE.writeValueAsString(index));
        assertEquals(index, IndexReader.read(file));
        assertEquals(BEFORE.readValue(file.toFile(), ModelIndex.class), IndexReader.read(file));
        // keys left out, a null definition, and content after the index, which the mapper never read
        String sparse = "{\"format\": 1, \"abstraction\": {\"name\": \"n\", \"definition\": null},"
                + " \"scenarios\": [{\"faulty\": false, \"samples\": 1, \"models\": [{\"states\": 2,"
                + " \"samples\": 1}]}]} trailing";
        Files.writeString(file, sparse);
        assertEquals(BEFORE.readValue(file.toFile(), ModelIndex.class), IndexReader.read(file));
    }

    /** Indexes written while learn stored its learning time still read: the time is checked and left out. */
    @Test
    void anIndexWithTheLearningTimeOfEarlierVersionsStillReads() throws Exception {
        String model = "{\"file\": \"s.dot\", \"states\": 2, \"samples\": 1, \"logs\": [\"a.log\"]";
        String index = "{\"format\": 1, \"scenarios\": [{\"name\": \"s\", \"faulty\": false, \"samples\": 1, "
                + "\"models\": [%s]}]}";
        Path now = Files.writeString(tmp.resolve("now.json"), String.format(index, model + "}"));
        Path before = Files.writeString(tmp.resolve("before.json"),
                String.format(index, model + ", \"learningMillis\": 41}"));
        assertEquals(IndexReader.read(now), IndexReader.read(before));
    }

    /**
     * A file far deeper or larger than any index (100,000 nested arrays, a 30 MB string) is one line naming the
     * file and what is wrong, not a crash of the reader.
     */
    @Test
    void aDeepOrHugeFileIsOneLineNamingIt() throws Exception {
        Path file = tmp.resolve("index.json");
        Files.writeString(file, "{\"format\": 1, \"x\": " + "[".repeat(100_000) + "]".repeat(100_000) + "}");
        BadInputException deep = assertThrows(BadInputException.class, () -> IndexReader.read(file));
        assertEquals(file + ":1: not a predmon model index: nested more than 64 levels deep", deep.getMessage());
        Files.writeString(file, "{\"format\": 1,\n \"x\": \"" + "a".repeat(30_000_000) + "\"}");
        BadInputException huge = assertThrows(BadInputException.class, () -> IndexReader.read(file));
        assertEquals(file + ":2: not a predmon model index: a string longer than 1000000 characters",
                huge.getMessage());
    }

    /** Broken JSON gets the parser's message, as before; what follows the index is not read, as before. */
    @Test
    void textThatIsNotJsonGetsTheMessageItGotBefore() throws Exception {
        Path file = tmp.resolve("index.json");
        for (String text : List.of("{", "{\"format\": 1,\n\"abstraction\": {", "{\"format\": 1,,}", "nul",
                "\n\n{\"a\" 1}", "{\"format\": 1}\u0000", "{\"format\": 1} {")) {
            Files.writeString(file, text);
            Object before;
            try {
                before = BEFORE.readValue(file.toFile(), ModelIndex.class);
            } catch (JsonProcessingException e) {
                before = file + ":" + e.getLocation().getLineNr() + ": not a predmon model index: "
                        + e.getOriginalMessage();
            }
            Object after;
            try {
                after = IndexReader.read(file);
            } catch (BadInputException e) {
                after = e.getMessage();
            }
            assertEquals(before, after, text);
        }
    }

    @Test
    void anEmptyFileNamesItsLine() throws Exception {
        Path file = Files.writeString(tmp.resolve("index.json"), "");
        BadInputException e = assertThrows(BadInputException.class, () -> IndexReader.read(file));
        assertEquals(file + ":1: not a predmon model index: No content to map due to end-of-input", e.getMessage());
    }

    @Test
    void aMissingFileIsNamed() {
        Path file = tmp.resolve("index.json");
        BadInputException e = assertThrows(BadInputException.class, () -> IndexReader.read(file));
        assertEquals(file + ": missing; run 'predmon learn' first", e.getMessage());
    }

    @Test
    void aValueOfTheWrongTypeIsOneLineNamingItsPlace() throws Exception {
        Path file = tmp.resolve("index.json");
        Map<String, String> cases = Map.of(
                "{\"format\": 1,\n \"scenarios\": [{\"name\": \"s\",\n \"faulty\": \"yes\"}]}",
                "3: not a predmon model index: scenarios[0].faulty: expected true or false",
                "{\"format\": null}", "1: not a predmon model index: format: expected a whole number",
                "{\"format\": 1, \"colour\": 2}", "1: not a predmon model index: colour: unknown key 'colour' "
                        + "(allowed: abstraction, alphabet, forecast, format, learnId, scenarios)",
                "{\"format\": 1, \"alphabet\": [\"a\",\n 3]}", "2: not a predmon model index: alphabet[1]: expected a string",
                "{\"format\": 1, \"abstraction\": {\"hysteresis\": {\"a\": \"x\"}}}",
                "1: not a predmon model index: abstraction.hysteresis.a: expected a number",
                "[1, 2]", "1: not a predmon model index: (top): expected an object",
                "{\"scenarios\": []}", "1: not a predmon model index: (top): missing key 'format'",
                "{\"format\": 1, \"scenarios\": [{\"faulty\": true, \"samples\": 1,\n \"models\": [{"
                        + "\"states\": 1, \"samples\": 1, \"learningMillis\": 1.5}]}]}",
                "2: not a predmon model index: scenarios[0].models[0].learningMillis: expected a whole number",
                "{\"format\": 1, \"scenarios\": [{\"faulty\": true,\n \"models\": []}]}",
                "1: not a predmon model index: scenarios[0]: missing key 'samples'",
                "{\"format\": 1, \"scenarios\": [null]}",
                "1: not a predmon model index: scenarios[0]: expected an object");
        for (Map.Entry<String, String> c : cases.entrySet()) {
            Files.writeString(file, c.getKey());
            BadInputException e = assertThrows(BadInputException.class, () -> IndexReader.read(file), c.getKey());
            assertEquals(file + ":" + c.getValue(), e.getMessage());
        }
    }

    @Test
    void anIndexWithoutItsPartsIsNotOfTheFormat() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("models"));
        String scenario = "{\"format\": 1, \"abstraction\": {}, \"alphabet\": [], \"scenarios\": [{\"name\": \"s\","
                + " \"faulty\": false, \"samples\": 1";
        for (String text : List.of("{\"format\": 2}", "{\"format\": 1}", "{\"format\": 1, \"abstraction\": null,"
                + " \"alphabet\": [], \"scenarios\": []}", scenario + "}]}", scenario + ", \"models\": [{\"states\": 1,"
                + " \"samples\": 1, \"learningMillis\": 0}]}]}")) {
            Files.writeString(dir.resolve("index.json"), text);
            BadInputException e = assertThrows(BadInputException.class,
                    () -> ModelStore.read(dir, AbstractionFiles.defaults()), text);
            assertEquals(dir.resolve("index.json") + ": not a predmon model index of format 1", e.getMessage());
        }
    }
}
