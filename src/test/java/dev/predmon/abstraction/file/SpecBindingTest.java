package dev.predmon.abstraction.file;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.databind.node.TextNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@link SpecBinder} and {@link SpecWriter} against what Jackson's data binding did before them
 * ({@link DatabindOracle}): the same spec or the same error message for every file, and byte for byte the same
 * canonical JSON, so that the fingerprints of existing model directories stay valid.
 */
class SpecBindingTest {

    /** Raw JSON values put in place of each value of the files: every type, and the coercion edge cases. */
    private static final List<String> VALUES = List.of("null", "\"\"", "\" \"", "\" \\t\"", "\"x\"", "\"20\"",
            "\"20.5\"", "\"NaN\"", "\"Infinity\"", "\"-INF\"", "\"true\"", "20", "0", "-3", "20.5", "-0.0", "1e2", "1e999",
            "3000000000", "1.5e10", "99999999999999999999999", "true", "false", "[]", "[null]", "[\"x\"]",
            "[1]", "[{}]", "{}", "{\"x\": 1}", "{\"any\": true, \"symbol\": \"o_z\"}", "{\"above\": 1}");

    /** A continuous rule using every key of a rule, odd numbers and strings that need escapes. */
    private static final String RULE = "{\"protocol\": \"B\", \"command\": \"level\", \"client\": \"/c*\","
            + " \"input\": \"level_i\","
            + " \"description\": \"\\u00e9\\t\\\"q\\\" \\\\ \\u2028 </script>\", \"continuous\": true,"
            + " \"carry\": true, \"hysteresis\": 1,"
            + " \"replies\": [{\"range\": {\"atLeast\": -0.0, \"below\": 1e2}, \"symbol\": \"o_a\"},"
            + " {\"range\": {\"atLeast\": 100, \"atMost\": 1.5e10}, \"symbol\": \"o_b\"},"
            + " {\"range\": {\"above\": 1.5e10}, \"symbol\": \"o_c\"}, {\"range\": {\"below\": -0.0},"
            + " \"symbol\": \"o_d\"}]}";
    /** A file using every key of every record. */
    private static final String ALL_KEYS = "{\"runs\": {\"silence\": 30, \"tickRestart\": false,"
            + " \"description\": \"r\"},"
            + " \"warning\": {\"confirm\": 2, \"description\": \"w\"}, \"name\": \"all\", \"description\": \"d\","
            + " \"locations\": {\"zeta\": \"z\", \"Alpha\": \"A\", \"alpha\": \"a\", \"\\u00e9t\\u00e9\": \"e\"},"
            + " \"drop\": [{\"kind\": \"reply\", \"from\": \"/a\", \"to\": \"/b\", \"protocol\": \"P\","
            + " \"command\": \"c\", \"description\": \"x\"}],"
            + " \"safety\": {\"name\": \"s\", \"protocol\": \"B\", \"command\": \"level\", \"from\": \"/f\","
            + " \"to\": \"/t\", \"below\": 20},"
            + " \"rules\": [" + RULE + ", {\"protocol\": \"P\", \"command\": \"q\", \"input\": \"q_{loc}_i\","
            + " \"replies\": [{\"equals\": [\"1\", \"27503\"], \"symbol\": \"o_q_{loc}\"},"
            + " {\"any\": true, \"symbol\": \"o_q_{loc}_other\"}]}]}";

    /**
     * The built-ins as data binding read files, that is without their {@code properties} list (read on its own by
     * {@link PropertySpecs}) and their {@code ros2} section (read by {@link Ros2Specs}): the text the binding tests
     * below edit.
     */
    static String bound(String name) {
        try {
            ObjectNode tree = (ObjectNode) DatabindOracle.MAPPER.readTree(AbstractionFiles.builtinJson(name).orElseThrow());
            tree.remove("properties");
            tree.remove("ros2");
            return DatabindOracle.MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(tree);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void canonicalJsonOfTheBuiltInsIsWhatDataBindingWrote() throws AbstractionException {
        for (String name : AbstractionFiles.BUILTIN_NAMES) {
            DatabindOracle.Outcome before = DatabindOracle.fromJson(name, bound(name));
            assertNotNull(before.canonical(), before.error());
            String properties = AbstractionFiles.builtin(name).orElseThrow().canonicalJson()
                    .replaceAll(",\"properties\":\\[.*\\](?=,\"rules\")", "");
            assertEquals(before.canonical(), properties, name);
        }
    }

    /**
     * Models learned with a built-in carry its fingerprint: the properties list changed none (what is learned
     * depends only on the forecast's property, hashed in the older {@code safety} form).
     */
    @Test
    void theBuiltInsKeepTheFingerprintsOfModelsLearnedBeforeProperties() {
        assertEquals("caed5be02408e2d34599d484a8b487484f4d44ce2b93956c044ee1df3f33f821",
                AbstractionFiles.builtin("thesis").orElseThrow().fingerprint());
        assertEquals("3c9b533e07acef022c02e522d35a6dda131b3d8189b463cfa9062616a76d0148",
                AbstractionFiles.builtin("scope-fetch").orElseThrow().fingerprint());
    }

    /** The shipped models carry a fingerprint: it must still be the one of their abstraction file. */
    @Test
    void theShippedModelsKeepTheirFingerprint() throws Exception {
        Path file = Path.of("models", "abstraction.json");
        String json = Files.readString(file);
        Abstraction a = AbstractionFiles.load(file);
        assertEquals(json, a.canonicalJson(), "abstraction.json is its own canonical form");
        String withoutProperties = json.replaceAll(",\"properties\":\\[.*\\](?=,\"rules\")", "");
        assertEquals(DatabindOracle.fromJson(file.toString(), withoutProperties).canonical(), withoutProperties);
        assertTrue(Files.readString(Path.of("models", "index.json")).contains(a.fingerprint()));
    }

    @Test
    void everyKeyIsWrittenAsDataBindingWroteIt() throws Exception {
        DatabindOracle.Outcome before = DatabindOracle.fromJson("all.json", ALL_KEYS);
        assertNotNull(before.canonical(), before.error());
        assertEquals(before.canonical(), AbstractionFiles.fromJson("all.json", ALL_KEYS).canonicalJson());
    }

    /**
     * Each value of each built-in and of {@link #ALL_KEYS} replaced by a value of every type: the same spec or the
     * same message.
     */
    @Test
    void everyValueOfEveryTypeBindsAsBefore() throws IOException {
        int compared = 0;
        List<String> files = new ArrayList<>(List.of(ALL_KEYS));
        AbstractionFiles.BUILTIN_NAMES.forEach(name -> files.add(bound(name)));
        for (String file : files) {
            JsonNode tree = LocatedJson.parse(file).root();
            // Binding depends on where a value is, not on which rule or reply: two places of each kind suffice.
            Map<String, Integer> seen = new HashMap<>();
            for (String pointer : pointers(tree, "")) {
                if (seen.merge(pointer.replaceAll("/\\d+", "/*"), 1, Integer::sum) > 2) {
                    continue;
                }
                for (String value : VALUES) {
                    assertSameAsBefore(replaced(tree, pointer, value));
                    compared++;
                }
            }
        }
        assertTrue(compared > 1000, "compared " + compared);
    }

    /** Unknown keys first, last and beside bad values, in every object; keys left out of every object. */
    @Test
    void unknownAndMissingKeysAreReportedAsBefore() throws IOException {
        JsonNode tree = LocatedJson.parse(bound("thesis")).root();
        List<String> pointers = new ArrayList<>(List.of(""));
        pointers.addAll(pointers(tree, ""));
        for (String pointer : pointers) {
            if (tree.at(pointer).isObject()) {
                ObjectNode object = (ObjectNode) tree.at(pointer);
                List<String> keys = new ArrayList<>();
                object.fieldNames().forEachRemaining(keys::add);
                assertSameAsBefore(withKeys(tree, pointer, "{\"colour\": 1, ", keys, "}"));
                assertSameAsBefore(withKeys(tree, pointer, "{", keys, ", \"colour\": 1, \"size\": [1]}"));
                assertSameAsBefore(withKeys(tree, pointer, "{\"colour\": 1, ", keys, ", \"size\": []}"));
                for (String key : keys) {
                    List<String> fewer = new ArrayList<>(keys);
                    fewer.remove(key);
                    assertSameAsBefore(withKeys(tree, pointer, "{", fewer, "}"));
                    assertSameAsBefore(withKeys(tree, pointer, "{\"" + key + "\": [[]], \"zz\": 0, ", fewer, "}"));
                    assertSameAsBefore(withKeys(tree, pointer, "{\"zz\": 0, ", fewer, ", \"" + key + "\": {}}"));
                }
            }
        }
    }

    /** Random edits of the built-ins' text (deleted spans, inserted tokens, copied spans). */
    @Test
    void editedFilesReadAsBefore() {
        String[] tokens = {"{", "}", "[", "]", ",", ":", "\"", "null", "true", "false", "0", "-1", "1e999", "-0.0",
                "20.0", "\"NaN\"", "\"x\"", "\"{loc}\"", "\"equals\"", "\"any\"", "\"symbol\"", "\"values\"", "\n"};
        Random random = new Random(12);
        for (String name : AbstractionFiles.BUILTIN_NAMES) {
            String text = bound(name);
            for (int n = 0; n < 1500; n++) {
                StringBuilder s = new StringBuilder(text);
                for (int edits = 1 + random.nextInt(3); edits > 0; edits--) {
                    int at = random.nextInt(s.length());
                    switch (random.nextInt(3)) {
                        case 0 -> s.delete(at, Math.min(s.length(), at + 1 + random.nextInt(30)));
                        case 1 -> s.insert(at, tokens[random.nextInt(tokens.length)]);
                        default -> {
                            int from = random.nextInt(s.length());
                            s.insert(at, s.substring(from, Math.min(s.length(), from + 1 + random.nextInt(150))));
                        }
                    }
                }
                assertSameAsBefore(s.toString());
            }
        }
    }

    private static void assertSameAsBefore(String json) {
        DatabindOracle.Outcome before = DatabindOracle.fromJson("t.json", json);
        String error = null;
        String canonical = null;
        try {
            canonical = AbstractionFiles.fromJson("t.json", json).canonicalJson();
        } catch (AbstractionException e) {
            error = e.getMessage();
        }
        assertEquals(before.error(), error, json);
        assertEquals(before.canonical(), canonical, json);
        try {
            LocatedJson tree = LocatedJson.parse(json);
            if (tree.root().isObject()) {
                DatabindOracle.Outcome bound = DatabindOracle.bind("t.json", tree);
                if (bound.spec() != null) {
                    assertEquals(bound.spec(), SpecBinder.spec(tree.root()), json);
                    assertEquals(DatabindOracle.canonical(bound.spec()), SpecWriter.canonical(bound.spec()), json);
                }
            }
        } catch (IOException | AbstractionValidator.Invalid e) {
            // the message was compared above
        }
    }

    /** The pointers of every value below {@code node}, {@code node}'s own excluded. */
    private static List<String> pointers(JsonNode node, String at) {
        List<String> out = new ArrayList<>();
        if (node.isObject()) {
            for (Iterator<String> it = node.fieldNames(); it.hasNext(); ) {
                String child = at + "/" + LocatedJson.escape(it.next());
                out.add(child);
                out.addAll(pointers(node.at(child), child));
            }
        } else if (node.isArray()) {
            for (int i = 0; i < node.size(); i++) {
                out.add(at + "/" + i);
                out.addAll(pointers(node.get(i), at + "/" + i));
            }
        }
        return out;
    }

    private static final String HOLE = "\u0000hole\u0000";

    /** The tree's text, indented, with the value at {@code pointer} replaced by the raw JSON {@code value}. */
    private static String replaced(JsonNode tree, String pointer, String value) {
        if (pointer.isEmpty()) {
            return value;
        }
        JsonNode copy = tree.deepCopy();
        String parent = pointer.substring(0, pointer.lastIndexOf('/'));
        String last = pointer.substring(pointer.lastIndexOf('/') + 1).replace("~1", "/").replace("~0", "~");
        JsonNode container = parent.isEmpty() ? copy : copy.at(parent);
        if (container.isArray()) {
            ((ArrayNode) container).set(Integer.parseInt(last), TextNode.valueOf(HOLE));
        } else {
            ((ObjectNode) container).set(last, TextNode.valueOf(HOLE));
        }
        return text(copy).replace("\"" + HOLE.replace("\u0000", "\\u0000") + "\"", value);
    }

    /** The tree's text with the object at {@code pointer} rewritten as {@code before}, its {@code keys}, {@code after}. */
    private static String withKeys(JsonNode tree, String pointer, String before, List<String> keys, String after) {
        StringBuilder b = new StringBuilder(before.endsWith(", ") && keys.isEmpty()
                ? before.substring(0, before.length() - 2) : before);
        for (int i = 0; i < keys.size(); i++) {
            b.append(i == 0 ? "" : ", ").append('"').append(keys.get(i)).append("\": ")
                    .append(text(tree.at(pointer).get(keys.get(i))));
        }
        String rest = keys.isEmpty() && after.startsWith(", ") ? after.substring(2) : after;
        return replaced(tree, pointer, b + rest);
    }

    private static String text(JsonNode node) {
        try {
            return DatabindOracle.MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(node);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }
}
