package dev.predmon.abstraction;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.abstraction.AbstractionSpec.DropSpec;
import dev.predmon.abstraction.AbstractionSpec.RangeSpec;
import dev.predmon.abstraction.AbstractionSpec.ReplySpec;
import dev.predmon.abstraction.AbstractionSpec.RuleSpec;
import dev.predmon.abstraction.AbstractionSpec.RunsSpec;
import dev.predmon.abstraction.AbstractionSpec.SafetySpec;
import dev.predmon.abstraction.AbstractionSpec.WarningSpec;
import dev.predmon.abstraction.AbstractionValidator.Invalid;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

/**
 * Binds the JSON tree of an abstraction file to {@link AbstractionSpec}, by hand. Jackson's data binding did this
 * before, but building its mapper and introspecting the records cost a quarter of a second of every start, so
 * this class does what that strictly configured mapper did, error for error (a test holds it to the mapper's
 * results on thousands of files):
 * <ul>
 *   <li>an unknown key is an error that lists the allowed ones, reported only after the object's known keys bound
 *       without error, as the mapper buffered unknown keys of a record until its end;</li>
 *   <li>a number, {@code true} or {@code false} is never coerced to a number or a boolean, nor a string to either,
 *       except the strings {@code NaN}, {@code Infinity}, {@code INF}, {@code -Infinity} and {@code -INF} for a
 *       number (JSON cannot write them otherwise); an integer is fine for a {@code Double}, and a number or a
 *       boolean for a string (it becomes the text Jackson gives it: {@code 20}, {@code 20.5}, {@code true});</li>
 *   <li>{@code null} and an absent key are {@code null}; lists and maps keep {@code null} elements and values; so
 *       is a blank string (spaces, no other character) for a number or a boolean;</li>
 *   <li>a problem is an {@link Invalid} at the pointer of the offending value (or unknown key).</li>
 * </ul>
 */
final class SpecBinder {

    /** Reads one value that is not {@code null}. */
    private interface Reader<T> {
        T read(JsonNode node, String pointer) throws Invalid;
    }

    private static final Reader<String> STRING = SpecBinder::string;
    private static final Reader<Double> DOUBLE = SpecBinder::number;
    private static final Reader<Boolean> BOOLEAN = SpecBinder::bool;

    // The keys of each record, with the reader of each key's value (what the record component's type asks for).
    private static final Map<String, Reader<?>> TOP = Map.of("name", STRING, "description", STRING,
            "drop", list(SpecBinder::drop), "locations", SpecBinder::locations, "rules", list(SpecBinder::rule),
            "safety", SpecBinder::safety, "warning", SpecBinder::warning, "runs", SpecBinder::runs);
    private static final Map<String, Reader<?>> DROP = Map.of("kind", STRING, "from", STRING, "to", STRING,
            "protocol", STRING, "command", STRING, "description", STRING);
    private static final Map<String, Reader<?>> RULE = Map.of("protocol", STRING, "command", STRING,
            "client", STRING, "input", STRING, "description", STRING, "continuous", BOOLEAN, "carry", BOOLEAN,
            "hysteresis", DOUBLE, "replies", list(SpecBinder::reply));
    /** {@code equals} is the JSON name of {@link ReplySpec#values()}. */
    private static final Map<String, Reader<?>> REPLY = Map.of("any", BOOLEAN, "equals", list(STRING),
            "range", SpecBinder::range, "symbol", STRING);
    private static final Map<String, Reader<?>> RANGE = Map.of("above", DOUBLE, "atLeast", DOUBLE,
            "below", DOUBLE, "atMost", DOUBLE);
    private static final Map<String, Reader<?>> SAFETY = Map.of("name", STRING, "protocol", STRING,
            "command", STRING, "from", STRING, "to", STRING, "below", DOUBLE);
    private static final Map<String, Reader<?>> WARNING = Map.of("confirm", (Reader<Integer>) SpecBinder::integer,
            "description", STRING);
    private static final Map<String, Reader<?>> RUNS = Map.of("tickRestart", BOOLEAN, "silence", DOUBLE,
            "description", STRING);

    private SpecBinder() {
    }

    /** The spec the tree gives; the top is an object. */
    static AbstractionSpec spec(JsonNode root) throws Invalid {
        Map<String, Object> f = fields(root, "", TOP);
        return new AbstractionSpec((String) f.get("name"), (String) f.get("description"), cast(f.get("drop")),
                cast(f.get("locations")), cast(f.get("rules")), (SafetySpec) f.get("safety"),
                (WarningSpec) f.get("warning"), (RunsSpec) f.get("runs"));
    }

    private static DropSpec drop(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, DROP);
        return new DropSpec((String) f.get("kind"), (String) f.get("from"), (String) f.get("to"),
                (String) f.get("protocol"), (String) f.get("command"), (String) f.get("description"));
    }

    private static RuleSpec rule(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, RULE);
        return new RuleSpec((String) f.get("protocol"), (String) f.get("command"), (String) f.get("client"),
                (String) f.get("input"), (String) f.get("description"), (Boolean) f.get("continuous"),
                (Boolean) f.get("carry"), (Double) f.get("hysteresis"), cast(f.get("replies")));
    }

    private static ReplySpec reply(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, REPLY);
        return new ReplySpec((Boolean) f.get("any"), cast(f.get("equals")), (RangeSpec) f.get("range"),
                (String) f.get("symbol"));
    }

    private static RangeSpec range(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, RANGE);
        return new RangeSpec((Double) f.get("above"), (Double) f.get("atLeast"), (Double) f.get("below"),
                (Double) f.get("atMost"));
    }

    private static SafetySpec safety(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, SAFETY);
        return new SafetySpec((String) f.get("name"), (String) f.get("protocol"), (String) f.get("command"),
                (String) f.get("from"), (String) f.get("to"), (Double) f.get("below"));
    }

    private static WarningSpec warning(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, WARNING);
        return new WarningSpec((Integer) f.get("confirm"), (String) f.get("description"));
    }

    private static RunsSpec runs(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, RUNS);
        return new RunsSpec((Boolean) f.get("tickRestart"), (Double) f.get("silence"), (String) f.get("description"));
    }

    /**
     * The values of an object's keys, each read by its reader in {@code keys}; absent keys are absent. Known keys
     * are read in the order of the text, so the first bad value is the first reported; then the first unknown key.
     */
    private static Map<String, Object> fields(JsonNode node, String at, Map<String, Reader<?>> keys) throws Invalid {
        if (!node.isObject()) {
            throw expected(at, "an object");
        }
        Map<String, Object> values = new HashMap<>();
        String unknown = null;
        for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            Reader<?> reader = keys.get(e.getKey());
            if (reader == null) {
                unknown = unknown == null ? e.getKey() : unknown;
                continue;
            }
            values.put(e.getKey(), nullable(reader, e.getValue(), at + "/" + LocatedJson.escape(e.getKey())));
        }
        if (unknown != null) {
            throw new Invalid(at + "/" + LocatedJson.escape(unknown), "unknown key '" + unknown + "' (allowed: "
                    + String.join(", ", new TreeSet<>(keys.keySet())) + ")");
        }
        return values;
    }

    private static <T> T nullable(Reader<T> reader, JsonNode node, String at) throws Invalid {
        return node.isNull() ? null : reader.read(node, at);
    }

    /** A list whose elements {@code element} reads; it may hold {@code null}s, so it is an {@link ArrayList}. */
    private static <T> Reader<List<T>> list(Reader<T> element) {
        return (node, at) -> {
            if (!node.isArray()) {
                throw expected(at, "an array");
            }
            List<T> list = new ArrayList<>(node.size());
            for (int i = 0; i < node.size(); i++) {
                list.add(nullable(element, node.get(i), at + "/" + i));
            }
            return list;
        };
    }

    /** Location names to abbreviations, in the order of the text (the canonical form sorts them). */
    private static Map<String, String> locations(JsonNode node, String at) throws Invalid {
        if (!node.isObject()) {
            throw expected(at, "an object");
        }
        Map<String, String> map = new LinkedHashMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            map.put(e.getKey(), nullable(STRING, e.getValue(), at + "/" + LocatedJson.escape(e.getKey())));
        }
        return map;
    }

    /** A string; a number or a boolean becomes its text, as Jackson's string binding made it. */
    private static String string(JsonNode node, String at) throws Invalid {
        if (node.isTextual()) {
            return node.textValue();
        }
        if (node.isNumber()) {
            return String.valueOf(node.numberValue());
        }
        if (node.isBoolean()) {
            return String.valueOf(node.booleanValue());
        }
        throw expected(at, "a string");
    }

    /** A number; of strings only the names of the values JSON has no number for. */
    private static Double number(JsonNode node, String at) throws Invalid {
        if (node.isNumber()) {
            return node.doubleValue();
        }
        if (node.isTextual()) {
            switch (node.textValue()) {
                case "NaN" -> {
                    return Double.NaN;
                }
                case "Infinity", "INF" -> {
                    return Double.POSITIVE_INFINITY;
                }
                case "-Infinity", "-INF" -> {
                    return Double.NEGATIVE_INFINITY;
                }
                default -> {
                    if (blank(node)) {
                        return null;
                    }
                }
            }
        }
        throw expected(at, "a number");
    }

    /** An integer; a fraction is cut to its integer part, as Jackson did; beyond an int is an error. */
    private static Integer integer(JsonNode node, String at) throws Invalid {
        if (blank(node)) {
            return null;
        }
        if (!node.isNumber()) {
            throw expected(at, "a number");
        }
        if (!node.canConvertToInt()) {
            String text = String.valueOf(node.numberValue());
            int digits = text.length() - (text.startsWith("-") ? 1 : 0);
            throw new Invalid(at, String.format("Numeric value (%s) out of range of int (%d - %s)",
                    text.length() < 1000 ? text : "[Integer with " + digits + " digits]",
                    Integer.MIN_VALUE, Integer.MAX_VALUE));
        }
        return node.intValue();
    }

    private static Boolean bool(JsonNode node, String at) throws Invalid {
        if (node.isBoolean()) {
            return node.booleanValue();
        }
        if (blank(node)) {
            return null;
        }
        throw expected(at, "true or false");
    }

    /**
     * Whether a string is blank but not empty: all its characters are spaces or control characters. Jackson read
     * such a string as null for a number or a boolean (and the empty string as an error), so this does too.
     */
    private static boolean blank(JsonNode node) {
        if (!node.isTextual() || node.textValue().isEmpty()) {
            return false;
        }
        return node.textValue().chars().allMatch(c -> c <= ' ');
    }

    private static Invalid expected(String at, String what) {
        return new Invalid(at, "expected " + what);
    }

    @SuppressWarnings("unchecked")
    private static <T> T cast(Object value) {
        return (T) value;
    }
}
