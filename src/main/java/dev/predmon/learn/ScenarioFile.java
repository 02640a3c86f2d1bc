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

/**
 * A scenario's {@code scenario.json}, {@code {"faulty": true|false, "description": "..."}}, read strictly as the
 * abstraction loader reads its file: an unknown key (a typo such as {@code "descripton"}) or a value of the wrong
 * type is rejected at its line and column, never ignored.
 *
 * @param faulty      whether the scenario's runs violate the safety property
 * @param description free text, {@code ""} when absent
 */
public record ScenarioFile(boolean faulty, String description) {

    /** The file's name inside a scenario directory. */
    public static final String NAME = "scenario.json";

    private static final String SHAPE = "{\"faulty\": true|false, \"description\": \"...\"}";
    private static final JsonFactory JSON = new JsonFactory();

    /** Reads and checks {@code json}. */
    public static ScenarioFile read(Path json) throws BadInputException {
        if (!Files.exists(json)) {
            throw new BadInputException(json + ": missing; write " + SHAPE);
        }
        if (!Files.isRegularFile(json)) {
            throw new BadInputException(json + ": not a regular file; expected " + SHAPE);
        }
        Boolean faulty = null;
        String description = "";
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
                    default -> throw new BadInputException(at(json, where) + "unknown key '" + key
                            + "' (allowed: description, faulty)");
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
        return new ScenarioFile(faulty, description);
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
