package dev.predmon.abstraction.file;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.abstraction.file.AbstractionValidator.Invalid;
import dev.predmon.parse.RecordKind;
import dev.predmon.property.Event;
import dev.predmon.property.RecordMatch;
import dev.predmon.property.Scope;
import dev.predmon.property.ValueReader;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;

/**
 * The parts every kind of property in an abstraction file is made of, read with each problem at its JSON pointer:
 * events (a record matcher or a list of them), values (a reply's number), scopes, and the checks of the JSON itself
 * (an object, its allowed keys, a required key, a string, a number). {@link PropertySpecs} reads the properties, each
 * kind from these parts.
 */
final class PropertyParts {

    private static final Set<String> MATCH = Set.of("kind", "protocol", "command", "from", "to", "argument", "reply");
    private static final Set<String> VALUE = Set.of("protocol", "command", "from", "to");

    private PropertyParts() {
    }

    static Scope scope(JsonNode node, String at) throws Invalid {
        object(node, at, "a scope: {\"from\": event, \"until\": event}");
        keys(node, at, Set.of("from", "until"));
        return new Scope(event(need(node, at, "from"), at + "/from"), event(need(node, at, "until"), at + "/until"));
    }

    static ValueReader value(JsonNode node, String at) throws Invalid {
        object(node, at, "a value: {\"protocol\": ..., \"command\": ...} with optional from and to ports");
        keys(node, at, VALUE);
        String from = text(node, at, "from", false);
        String to = text(node, at, "to", false);
        return new ValueReader(text(node, at, "protocol", true), text(node, at, "command", true),
                from == null ? "" : from, to == null ? "" : to);
    }

    static Event event(JsonNode node, String at) throws Invalid {
        List<RecordMatch> matches = new ArrayList<>();
        if (node.isArray()) {
            if (node.isEmpty()) {
                throw new Invalid(at, "expected at least one record matcher");
            }
            for (int i = 0; i < node.size(); i++) {
                matches.add(match(node.get(i), at + "/" + i));
            }
        } else {
            matches.add(match(node, at));
        }
        return new Event(matches);
    }

    static RecordMatch match(JsonNode node, String at) throws Invalid {
        object(node, at, "an event: a record matcher such as {\"protocol\": \"GoTo\", \"command\": \"getStatus\","
                + " \"reply\": \"3\"}, or a list of them");
        keys(node, at, MATCH);
        if (node.isEmpty()) {
            throw new Invalid(at, "an event needs at least one of " + new TreeSet<>(MATCH));
        }
        RecordKind kind = null;
        String k = text(node, at, "kind", false);
        if (k != null) {
            kind = switch (k.toLowerCase(Locale.ROOT)) {
                case "command" -> RecordKind.COMMAND;
                case "reply" -> RecordKind.REPLY;
                case "tick" -> RecordKind.TICK;
                default -> throw new Invalid(at + "/kind", "kind '" + k + "' is not one of command, reply, tick");
            };
        }
        return new RecordMatch(kind, text(node, at, "protocol", false), text(node, at, "command", false),
                text(node, at, "from", false), text(node, at, "to", false), strings(node, at, "argument"),
                strings(node, at, "reply"));
    }

    static List<String> strings(JsonNode node, String at, String key) throws Invalid {
        JsonNode v = node.get(key);
        if (v == null) {
            return null;
        }
        List<String> values = new ArrayList<>();
        if (v.isTextual()) {
            values.add(v.textValue());
        } else if (v.isArray() && !v.isEmpty()) {
            for (int i = 0; i < v.size(); i++) {
                if (!v.get(i).isTextual()) {
                    throw new Invalid(at + "/" + key + "/" + i, "expected a string");
                }
                values.add(v.get(i).textValue());
            }
        } else {
            throw new Invalid(at + "/" + key, "expected a string or a non-empty list of strings (any of them)");
        }
        return values;
    }

    static void object(JsonNode node, String at, String what) throws Invalid {
        if (node == null || !node.isObject()) {
            throw new Invalid(at, "expected " + what);
        }
    }

    static void keys(JsonNode node, String at, Set<String> allowed) throws Invalid {
        for (Iterator<String> it = node.fieldNames(); it.hasNext(); ) {
            String key = it.next();
            if (!allowed.contains(key)) {
                throw new Invalid(at + "/" + LocatedJson.escape(key), "unknown key '" + key + "' (allowed: "
                        + String.join(", ", new TreeSet<>(allowed)) + ")");
            }
        }
    }

    static JsonNode need(JsonNode node, String at, String key) throws Invalid {
        JsonNode v = node.get(key);
        if (v == null || v.isNull()) {
            throw new Invalid(at, "missing required key '" + key + "'");
        }
        return v;
    }

    static String text(JsonNode node, String at, String key, boolean required) throws Invalid {
        JsonNode v = node.get(key);
        if (v == null || v.isNull()) {
            if (required) {
                throw new Invalid(at, "missing required key '" + key + "'");
            }
            return null;
        }
        if (!v.isTextual() || v.textValue().isBlank()) {
            throw new Invalid(at + "/" + key, "expected a non-blank string");
        }
        return v.textValue();
    }

    /** A string of one line of at most {@code max} characters. */
    static String line(JsonNode node, String at, String key, int max) throws Invalid {
        String s = text(node, at, key, true);
        if (s.length() > max || s.chars().anyMatch(Character::isISOControl)) {
            throw new Invalid(at + "/" + key, "'" + key + "' must be one line of at most " + max + " characters");
        }
        return s;
    }

    static Double number(JsonNode node, String at, String key) throws Invalid {
        JsonNode v = node.get(key);
        if (v == null || v.isNull()) {
            return null;
        }
        if (!v.isNumber() || !Double.isFinite(v.doubleValue())) {
            throw new Invalid(at + "/" + key, "expected a finite number");
        }
        return v.doubleValue();
    }
}
