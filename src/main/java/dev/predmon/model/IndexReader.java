package dev.predmon.model;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.BadInputException;
import dev.predmon.abstraction.file.LocatedJson;

import java.io.FileNotFoundException;
import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * Reads {@code models/index.json} into a {@link ModelIndex}: parsed by {@link LocatedJson} (jackson-core) and bound
 * by hand. An {@code ObjectMapper} did this before, but building one and introspecting the records cost a tenth of
 * a second of every command that reads models; writing the index ({@code learn}) still uses one.
 *
 * <p>It reads what {@link ModelStore#write} writes and what that mapper read of it: a missing string, list or
 * object is {@code null}; a number or a boolean is required (the mapper failed on null primitives); an unknown key
 * is an error. Values of the wrong type are errors naming where they are; the mapper converted some of them
 * ({@code "1"} for {@code 1}), which only a hand-edited index holds, and crashed on a {@code null} scenario or model.
 */
final class IndexReader {

    /** The learning time that earlier indexes stored per model: accepted and ignored. */
    private static final String LEARNING_MILLIS = "learningMillis";

    private final Path file;
    private final LocatedJson tree;

    private IndexReader(Path file, LocatedJson tree) {
        this.file = file;
        this.tree = tree;
    }

    /**
     * The index in {@code file}.
     *
     * @throws BadInputException one line: the file is missing, is not JSON ({@code file:line: not a predmon model
     *                           index: reason}), or holds a value of the wrong type (the same, naming where)
     */
    static ModelIndex read(Path file) throws BadInputException {
        LocatedJson tree;
        try {
            tree = LocatedJson.readValue(file.toFile());
        } catch (NoSuchFileException | FileNotFoundException e) {
            throw new BadInputException(file + ": missing; run 'predmon learn' first");
        } catch (JsonProcessingException e) {
            // a parse error has a position; a JSON error without one (none known today) still names the file
            JsonLocation l = e.getLocation();
            throw new BadInputException(file + (l == null ? "" : ":" + l.getLineNr()) + ": not a predmon model index: "
                    + e.getOriginalMessage());
        } catch (IOException e) {
            throw BadInputException.cannotRead(file, e);
        }
        return new IndexReader(file, tree).index(tree.root(), "");
    }

    private ModelIndex index(JsonNode n, String at) throws BadInputException {
        keys(n, at, "format", "abstraction", "alphabet", "scenarios", "forecast", "learnId");
        JsonNode scenarios = array(n, at, "scenarios");
        List<ModelIndex.Scenario> list = null;
        if (scenarios != null) {
            list = new ArrayList<>();
            for (int i = 0; i < scenarios.size(); i++) {
                list.add(scenario(scenarios.get(i), at + "/scenarios/" + i));
            }
        }
        JsonNode abstraction = n.get("abstraction");
        return new ModelIndex(integer(n, at, "format"), abstraction == null || abstraction.isNull() ? null
                : abstraction(abstraction, at + "/abstraction"), strings(n, at, "alphabet"), list,
                n.hasNonNull("forecast") ? string(n, at, "forecast") : null, string(n, at, "learnId"));
    }

    private ModelIndex.AbstractionInfo abstraction(JsonNode n, String at) throws BadInputException {
        keys(n, at, "name", "fingerprint", "definition", "hysteresis");
        Map<String, Double> hysteresis = null;
        JsonNode h = n.get("hysteresis");
        if (h != null && !h.isNull()) {
            if (!h.isObject()) {
                throw problem(at + "/hysteresis", "expected an object");
            }
            hysteresis = new LinkedHashMap<>();
            for (Iterator<Map.Entry<String, JsonNode>> it = h.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> e = it.next();
                if (!e.getValue().isNumber()) {
                    throw problem(at + "/hysteresis/" + LocatedJson.escape(e.getKey()), "expected a number");
                }
                hysteresis.put(e.getKey(), e.getValue().doubleValue());
            }
        }
        // the definition is kept as it is: JSON null included, which the mapper read as a null node too
        return new ModelIndex.AbstractionInfo(string(n, at, "name"), string(n, at, "fingerprint"),
                n.get("definition"), hysteresis);
    }

    private ModelIndex.Scenario scenario(JsonNode n, String at) throws BadInputException {
        keys(n, at, "name", "faulty", "description", "samples", "models", "violates");
        JsonNode models = array(n, at, "models");
        List<ModelIndex.Model> list = null;
        if (models != null) {
            list = new ArrayList<>();
            for (int i = 0; i < models.size(); i++) {
                list.add(model(models.get(i), at + "/models/" + i));
            }
        }
        JsonNode violates = n.get("violates");
        if (violates != null && !violates.isTextual()) {
            throw problem(at + "/violates", "expected the id of a property, as a string");
        }
        return new ModelIndex.Scenario(string(n, at, "name"), bool(n, at, "faulty"), string(n, at, "description"),
                integer(n, at, "samples"), list, violates == null ? null : violates.textValue());
    }

    private ModelIndex.Model model(JsonNode n, String at) throws BadInputException {
        keys(n, at, "file", "states", "samples", "logs", LEARNING_MILLIS);
        // Indexes written before learn stopped storing its timing still read; the value is checked, not kept.
        JsonNode millis = n.get(LEARNING_MILLIS);
        if (millis != null && (!millis.isIntegralNumber() || !millis.canConvertToLong())) {
            throw problem(at + "/" + LEARNING_MILLIS, "expected a whole number");
        }
        return new ModelIndex.Model(string(n, at, "file"), integer(n, at, "states"), integer(n, at, "samples"),
                strings(n, at, "logs"));
    }

    /** Checks that {@code n} is an object with no other keys than {@code allowed}. */
    private void keys(JsonNode n, String at, String... allowed) throws BadInputException {
        if (!n.isObject()) {
            throw problem(at, "expected an object");
        }
        Set<String> known = Set.of(allowed);
        for (Iterator<String> it = n.fieldNames(); it.hasNext(); ) {
            String key = it.next();
            if (!known.contains(key)) {
                throw problem(at + "/" + LocatedJson.escape(key), "unknown key '" + key + "' (allowed: "
                        + String.join(", ", new TreeSet<>(known)) + ")");
            }
        }
    }

    /** The array at {@code key}, or null when it is absent or null. */
    private JsonNode array(JsonNode n, String at, String key) throws BadInputException {
        JsonNode v = n.get(key);
        if (v == null || v.isNull()) {
            return null;
        }
        if (!v.isArray()) {
            throw problem(at + "/" + key, "expected an array");
        }
        return v;
    }

    private List<String> strings(JsonNode n, String at, String key) throws BadInputException {
        JsonNode v = array(n, at, key);
        if (v == null) {
            return null;
        }
        List<String> list = new ArrayList<>();
        for (int i = 0; i < v.size(); i++) {
            if (!v.get(i).isTextual()) {
                throw problem(at + "/" + key + "/" + i, "expected a string");
            }
            list.add(v.get(i).textValue());
        }
        return list;
    }

    private String string(JsonNode n, String at, String key) throws BadInputException {
        JsonNode v = n.get(key);
        if (v == null || v.isNull()) {
            return null;
        }
        if (!v.isTextual()) {
            throw problem(at + "/" + key, "expected a string");
        }
        return v.textValue();
    }

    private int integer(JsonNode n, String at, String key) throws BadInputException {
        JsonNode v = required(n, at, key);
        if (!v.isIntegralNumber() || !v.canConvertToInt()) {
            throw problem(at + "/" + key, "expected a whole number");
        }
        return v.intValue();
    }

    private boolean bool(JsonNode n, String at, String key) throws BadInputException {
        JsonNode v = required(n, at, key);
        if (!v.isBoolean()) {
            throw problem(at + "/" + key, "expected true or false");
        }
        return v.booleanValue();
    }

    /** The value of a key that must be there: a number or a boolean, which the mapper would not take as absent. */
    private JsonNode required(JsonNode n, String at, String key) throws BadInputException {
        JsonNode v = n.get(key);
        if (v == null) {
            throw problem(at, "missing key '" + key + "'");
        }
        return v;
    }

    private BadInputException problem(String pointer, String reason) {
        JsonLocation l = tree.locate(pointer);
        return new BadInputException(file + (l == null ? "" : ":" + l.getLineNr()) + ": not a predmon model index: "
                + LocatedJson.readable(pointer) + ": " + reason);
    }
}
