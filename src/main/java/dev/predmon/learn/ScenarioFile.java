package dev.predmon.learn;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import dev.predmon.BadInputException;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * A scenario's {@code scenario.json}, {@code {"faulty": true|false, "description": "...", "violates": "<id>"}},
 * read strictly as the abstraction loader reads its file: an unknown key (a typo such as {@code "descripton"}), a
 * value of the wrong type or a property the abstraction does not define is rejected at its line and column, never
 * ignored.
 *
 * @param faulty      whether the scenario's runs violate a property
 * @param description free text, {@code ""} when absent
 * @param violates    the id of the property a faulty scenario's runs violate, null when the file does not say (then
 *                    it is the property the forecast follows)
 */
public record ScenarioFile(boolean faulty, String description, String violates) {

    /** The file's name inside a scenario directory. */
    public static final String NAME = "scenario.json";

    private static final String SHAPE = "{\"faulty\": true|false, \"description\": \"...\"}";

    /** A file that does not say which property its runs violate. */
    public ScenarioFile(boolean faulty, String description) {
        this(faulty, description, null);
    }
    private static final JsonFactory JSON = new JsonFactory();

    /** Reads and checks {@code json}, whatever property it names. */
    public static ScenarioFile read(Path json) throws BadInputException {
        return read(json, null);
    }

    /**
     * Reads and checks {@code json}; its {@code violates}, when it has one, must be one of {@code properties} (the
     * ids of the abstraction's properties, in file order; null to accept any).
     */
    public static ScenarioFile read(Path json, List<String> properties) throws BadInputException {
        if (!Files.exists(json)) {
            throw new BadInputException(json + ": missing; write " + SHAPE);
        }
        if (!Files.isRegularFile(json)) {
            throw new BadInputException(json + ": not a regular file; expected " + SHAPE);
        }
        Boolean faulty = null;
        String description = "";
        String violates = null;
        JsonLocation violatesAt = null;
        try (JsonParser p = JSON.createParser(json.toFile())) {
            if (p.nextToken() != JsonToken.START_OBJECT) {
                throw new BadInputException(at(json, p.currentTokenLocation()) + "expected an object " + SHAPE);
            }
            for (JsonToken t = p.nextToken(); t == JsonToken.FIELD_NAME; t = p.nextToken()) {
                String key = p.currentName();
                JsonLocation where = p.currentTokenLocation();
                JsonToken value = p.nextToken();
                switch (key) {
                    case "faulty" -> {
                        if (!value.isBoolean()) {
                            throw new BadInputException(at(json, p.currentTokenLocation()) + "\"faulty\": expected true or false");
                        }
                        faulty = value == JsonToken.VALUE_TRUE;
                    }
                    case "description" -> {
                        if (value != JsonToken.VALUE_STRING) {
                            throw new BadInputException(at(json, p.currentTokenLocation()) + "\"description\": expected a string");
                        }
                        description = p.getText();
                    }
                    case "violates" -> {
                        violatesAt = p.currentTokenLocation();
                        if (value != JsonToken.VALUE_STRING) {
                            throw new BadInputException(at(json, violatesAt) + "\"violates\": expected the id of a "
                                    + "property, as a string");
                        }
                        violates = p.getText();
                        if (properties != null && !properties.contains(violates)) {
                            throw new BadInputException(at(json, violatesAt) + "\"violates\": '" + violates
                                    + "' is not a property of the abstraction (its properties: "
                                    + String.join(", ", properties) + ")");
                        }
                    }
                    default -> throw new BadInputException(at(json, where) + "unknown key '" + key
                            + "' (allowed: description, faulty, violates)");
                }
            }
            if (p.nextToken() != null) {
                throw new BadInputException(at(json, p.currentTokenLocation()) + "expected nothing after the object");
            }
        } catch (JsonProcessingException e) {
            throw new BadInputException(at(json, e.getLocation()) + "invalid JSON: " + firstLine(e.getOriginalMessage()));
        } catch (IOException e) {
            throw BadInputException.cannotRead(json, e);
        }
        if (faulty == null) {
            throw new BadInputException(json + ": expected an object with a boolean \"faulty\"");
        }
        if (violates != null && !faulty) {
            throw new BadInputException(at(json, violatesAt) + "\"violates\" names the property a faulty scenario's "
                    + "runs violate, and this scenario is not faulty (\"faulty\": false)");
        }
        return new ScenarioFile(faulty, description, violates);
    }

    private static String at(Path json, JsonLocation l) {
        return l == null || l.getLineNr() < 1 ? json + ": " : json + ":" + l.getLineNr() + ":" + l.getColumnNr() + ": ";
    }

    private static String firstLine(String s) {
        String m = s == null ? "" : s.strip();
        int nl = m.indexOf('\n');
        return nl < 0 ? m : m.substring(0, nl);
    }
}
