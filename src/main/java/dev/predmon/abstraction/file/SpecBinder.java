package dev.predmon.abstraction.file;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.abstraction.file.AbstractionSpec.DropSpec;
import dev.predmon.abstraction.file.AbstractionSpec.RangeSpec;
import dev.predmon.abstraction.file.AbstractionSpec.ReplySpec;
import dev.predmon.abstraction.file.AbstractionSpec.RuleSpec;
import dev.predmon.abstraction.file.AbstractionSpec.RunsSpec;
import dev.predmon.abstraction.file.AbstractionSpec.SafetySpec;
import dev.predmon.abstraction.file.AbstractionSpec.UnderWaySpec;
import dev.predmon.abstraction.file.AbstractionSpec.WarningSpec;
import dev.predmon.abstraction.file.AbstractionValidator.Invalid;

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

    /**
     * What a key's value is read as: the type of its record component. (An enum and a switch rather than a reader
     * object per type: a dozen lambdas cost milliseconds to bootstrap at every start.)
     */
    private enum Type {
        STRING, NUMBER, INTEGER, BOOLEAN, LOCATIONS, DROP, RULE, REPLY, RANGE, SAFETY, WARNING, RUNS, UNDER_WAY,
        STRINGS(STRING), DROPS(DROP), RULES(RULE), REPLIES(REPLY), UNDER_WAYS(UNDER_WAY);

        /** For a list, the type of its elements. */
        final Type element;

        Type() {
            this(null);
        }

        Type(Type element) {
            this.element = element;
        }
    }

    // The keys of each record, with the type of each key's value.
    private static final Map<String, Type> TOP = Map.of("name", Type.STRING, "description", Type.STRING,
            "drop", Type.DROPS, "locations", Type.LOCATIONS, "rules", Type.RULES, "safety", Type.SAFETY,
            "warning", Type.WARNING, "runs", Type.RUNS);
    private static final Map<String, Type> DROP = Map.of("kind", Type.STRING, "from", Type.STRING,
            "to", Type.STRING, "protocol", Type.STRING, "command", Type.STRING, "description", Type.STRING);
    private static final Map<String, Type> RULE = Map.of("protocol", Type.STRING, "command", Type.STRING,
            "client", Type.STRING, "input", Type.STRING, "description", Type.STRING, "continuous", Type.BOOLEAN,
            "carry", Type.BOOLEAN, "hysteresis", Type.NUMBER, "replies", Type.REPLIES);
    /** {@code equals} is the JSON name of {@link ReplySpec#values()}. */
    private static final Map<String, Type> REPLY = Map.of("any", Type.BOOLEAN, "equals", Type.STRINGS,
            "range", Type.RANGE, "symbol", Type.STRING);
    private static final Map<String, Type> RANGE = Map.of("above", Type.NUMBER, "atLeast", Type.NUMBER,
            "below", Type.NUMBER, "atMost", Type.NUMBER);
    private static final Map<String, Type> SAFETY = Map.of("name", Type.STRING, "protocol", Type.STRING,
            "command", Type.STRING, "from", Type.STRING, "to", Type.STRING, "below", Type.NUMBER, "action", Type.STRING,
            "underWay", Type.UNDER_WAYS);
    private static final Map<String, Type> UNDER_WAY = Map.of("skill", Type.STRING, "protocol", Type.STRING,
            "command", Type.STRING, "argument", Type.STRING);
    private static final Map<String, Type> WARNING = Map.of("confirm", Type.INTEGER, "description", Type.STRING);
    private static final Map<String, Type> RUNS = Map.of("tickRestart", Type.BOOLEAN, "silence", Type.NUMBER,
            "description", Type.STRING);

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
                (String) f.get("from"), (String) f.get("to"), (Double) f.get("below"), (String) f.get("action"),
                cast(f.get("underWay")));
    }

    private static UnderWaySpec underWay(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, UNDER_WAY);
        return new UnderWaySpec((String) f.get("skill"), (String) f.get("protocol"), (String) f.get("command"),
                (String) f.get("argument"));
    }

    private static WarningSpec warning(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, WARNING);
        return new WarningSpec((Integer) f.get("confirm"), (String) f.get("description"));
    }

    private static RunsSpec runs(JsonNode node, String at) throws Invalid {
        Map<String, Object> f = fields(node, at, RUNS);
        return new RunsSpec((Boolean) f.get("tickRestart"), (Double) f.get("silence"), (String) f.get("description"));
    }

    /** The value of {@code node} as {@code type}; {@code null} for JSON null. */
    private static Object read(Type type, JsonNode node, String at) throws Invalid {
        if (node.isNull()) {
            return null;
        }
        return switch (type) {
            case STRING -> string(node, at);
            case NUMBER -> number(node, at);
            case INTEGER -> integer(node, at);
            case BOOLEAN -> bool(node, at);
            case LOCATIONS -> locations(node, at);
            case DROP -> drop(node, at);
            case RULE -> rule(node, at);
            case REPLY -> reply(node, at);
            case RANGE -> range(node, at);
            case SAFETY -> safety(node, at);
            case WARNING -> warning(node, at);
            case RUNS -> runs(node, at);
            case UNDER_WAY -> underWay(node, at);
            case STRINGS, DROPS, RULES, REPLIES, UNDER_WAYS -> list(type.element, node, at);
        };
    }

    /**
     * The values of an object's keys, each read as its type in {@code keys}; absent keys are absent. Known keys
     * are read in the order of the text, so the first bad value is the first reported; then the first unknown key.
     */
    private static Map<String, Object> fields(JsonNode node, String at, Map<String, Type> keys) throws Invalid {
        if (!node.isObject()) {
            throw expected(at, "an object");
        }
        Map<String, Object> values = new HashMap<>();
        String unknown = null;
        for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            Type type = keys.get(e.getKey());
            if (type == null) {
                unknown = unknown == null ? e.getKey() : unknown;
                continue;
            }
            values.put(e.getKey(), read(type, e.getValue(), at + "/" + LocatedJson.escape(e.getKey())));
        }
        if (unknown != null) {
            throw new Invalid(at + "/" + LocatedJson.escape(unknown), "unknown key '" + unknown + "' (allowed: "
                    + String.join(", ", new TreeSet<>(keys.keySet())) + ")");
        }
        return values;
    }

    /** A list of {@code element}s; it may hold {@code null}s, so it is an {@link ArrayList}. */
    private static List<Object> list(Type element, JsonNode node, String at) throws Invalid {
        if (!node.isArray()) {
            throw expected(at, "an array");
        }
        List<Object> list = new ArrayList<>(node.size());
        for (int i = 0; i < node.size(); i++) {
            list.add(read(element, node.get(i), at + "/" + i));
        }
        return list;
    }

    /** Location names to abbreviations, in the order of the text (the canonical form sorts them). */
    private static Map<String, String> locations(JsonNode node, String at) throws Invalid {
        if (!node.isObject()) {
            throw expected(at, "an object");
        }
        Map<String, String> map = new LinkedHashMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            map.put(e.getKey(), (String) read(Type.STRING, e.getValue(), at + "/" + LocatedJson.escape(e.getKey())));
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
        String text = node.textValue();
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) > ' ') {
                return false;
            }
        }
        return true;
    }

    private static Invalid expected(String at, String what) {
        return new Invalid(at, "expected " + what);
    }

    // Only for values whose type the binder has checked against the schema: it names the generic type (a list of
    // rule specs, say) that a plain cast cannot check either.
    @SuppressWarnings({"unchecked", "TypeParameterUnusedInFormals"})
    private static <T> T cast(Object value) {
        return (T) value;
    }
}
