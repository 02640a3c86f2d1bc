package dev.predmon.abstraction.file;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.abstraction.file.AbstractionValidator.Invalid;
import dev.predmon.ros2.FieldPath;
import dev.predmon.ros2.TopicRule;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import static dev.predmon.abstraction.file.PropertyParts.keys;
import static dev.predmon.abstraction.file.PropertyParts.number;
import static dev.predmon.abstraction.file.PropertyParts.object;
import static dev.predmon.abstraction.file.PropertyParts.text;

/**
 * The {@code ros2} section of an abstraction file: a list of rules, each read into a {@link TopicRule} with each
 * problem at its JSON pointer.
 *
 * <p>A rule has a {@code topic} ({@code *} matches any characters), optionally a {@code type}, a {@code field} path,
 * optionally a {@code key} path, and the {@code protocol} and {@code command} of the records it gives. With
 * {@code scale} ({@code as-is}, {@code fraction}, {@code percent} or {@code auto}) it is a value rule; without, an
 * event rule, which may give {@code names} (value to word) and {@code atLeast}. {@code changes: true} gives a record
 * only when a key's value changes. {@code description} is for readers.
 */
final class Ros2Specs {

    private static final Set<String> KEYS = Set.of("topic", "type", "field", "key", "protocol", "command", "scale",
            "names", "atLeast", "changes", "description");
    private static final Map<String, TopicRule.Scale> SCALES = Map.of("as-is", TopicRule.Scale.AS_IS,
            "fraction", TopicRule.Scale.FRACTION, "percent", TopicRule.Scale.PERCENT, "auto", TopicRule.Scale.AUTO);

    private Ros2Specs() {
    }

    static List<TopicRule> read(JsonNode section) throws Invalid {
        if (!section.isArray() || section.isEmpty()) {
            throw new Invalid("/ros2", "expected a non-empty list of topic rules, such as {\"topic\":"
                    + " \"/battery_state\", \"field\": \"percentage\", \"protocol\": \"battery\", \"command\":"
                    + " \"percentage\", \"scale\": \"auto\"}");
        }
        List<TopicRule> rules = new ArrayList<>();
        for (int i = 0; i < section.size(); i++) {
            rules.add(rule(section.get(i), "/ros2/" + i));
        }
        return rules;
    }

    private static TopicRule rule(JsonNode node, String at) throws Invalid {
        object(node, at, "a topic rule: {\"topic\": ..., \"field\": ..., \"protocol\": ..., \"command\": ...}");
        keys(node, at, KEYS);
        String topic = text(node, at, "topic", true);
        if (!topic.startsWith("/") && !topic.startsWith("*")) {
            throw new Invalid(at + "/topic", "a topic starts with / (or * for any characters), got '" + topic + "'");
        }
        String type = text(node, at, "type", false);
        if (type != null && !type.matches("[A-Za-z0-9_]+/(msg/)?[A-Za-z0-9_]+")) {
            throw new Invalid(at + "/type", "a type is package/msg/Type or package/Type, got '" + type + "'");
        }
        String field = text(node, at, "field", true);
        FieldPath fieldPath = path(field, at + "/field");
        String key = text(node, at, "key", false);
        if (key != null) {
            FieldPath keyPath = path(key, at + "/key");
            if (keyPath.each() != fieldPath.each()
                    || (keyPath.each() && !keyPath.listPart().equals(fieldPath.listPart()))) {
                throw new Invalid(at + "/key", "the key must go through the same list as the field ("
                        + (fieldPath.each() ? fieldPath.listPart() : "none") + "), got '" + key + "'");
            }
        }
        String protocol = word(node, at, "protocol");
        String command = word(node, at, "command");
        TopicRule.Scale scale = null;
        String s = text(node, at, "scale", false);
        if (s != null) {
            scale = SCALES.get(s.toLowerCase(Locale.ROOT));
            if (scale == null) {
                throw new Invalid(at + "/scale", "scale '" + s + "' is not one of as-is, fraction, percent, auto");
            }
        }
        Map<String, String> names = names(node.get("names"), at + "/names");
        Double atLeast = number(node, at, "atLeast");
        if (scale != null && (names != null || atLeast != null)) {
            throw new Invalid(at + (names != null ? "/names" : "/atLeast"), "a value rule (with a scale) gives its"
                    + " number: names and atLeast are for event rules");
        }
        JsonNode changes = node.get("changes");
        if (changes != null && !changes.isBoolean()) {
            throw new Invalid(at + "/changes", "expected true or false");
        }
        return new TopicRule(topic, type, field, key, protocol, command, scale, names, atLeast,
                changes != null && changes.booleanValue());
    }

    private static FieldPath path(String text, String at) throws Invalid {
        try {
            return FieldPath.parse(text);
        } catch (IllegalArgumentException e) {
            throw new Invalid(at, e.getMessage());
        }
    }

    /** A protocol or command: what a record's field can hold, one word without spaces. */
    private static String word(JsonNode node, String at, String key) throws Invalid {
        String w = text(node, at, key, true);
        if (!w.matches("[^\\s]{1,80}")) {
            throw new Invalid(at + "/" + key, "'" + key + "' must be one word of at most 80 characters, got '" + w
                    + "'");
        }
        return w;
    }

    private static Map<String, String> names(JsonNode node, String at) throws Invalid {
        if (node == null || node.isNull()) {
            return null;
        }
        if (!node.isObject() || node.isEmpty()) {
            throw new Invalid(at, "expected an object of value to word, such as {\"6\": \"aborted\"}");
        }
        Map<String, String> names = new LinkedHashMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            String w = e.getValue().isTextual() ? e.getValue().textValue() : "";
            if (!w.matches("[^\\s]{1,80}")) {
                throw new Invalid(at + "/" + LocatedJson.escape(e.getKey()), "expected one word of at most 80"
                        + " characters");
            }
            names.put(e.getKey(), w);
        }
        return names;
    }
}
