package dev.predmon.forecast;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Supplier;

/**
 * A value of {@code forecast.json} with its path in the file ({@code properties.battery.threshold}), so that whatever
 * is wrong with it is told in one line that says where. The readers of every part of the file go through it; the
 * numbers they write go through {@link #number(ObjectNode, String, double)} ({@code null} for a number not known, as
 * JSON has no NaN).
 *
 * @param node the value
 * @param path where it is, keys joined by dots ({@code ""} for the file's top)
 */
record JsonAt(JsonNode node, String path) {

    /** The file's top. */
    static JsonAt root(JsonNode node) {
        return new JsonAt(node, "");
    }

    /** The path of {@code key} under this value. */
    String at(String key) {
        return path.isEmpty() ? key : path + "." + key;
    }

    /** What is wrong here, as the one line the user reads: {@code 'properties.battery.runs': -5, expected 0 or more}. */
    IllegalArgumentException wrong(String what) {
        return new IllegalArgumentException("'" + (path.isEmpty() ? "(top)" : path) + "': " + what);
    }

    /** The value of {@code key}, which must be there. */
    JsonAt get(String key) {
        JsonNode v = node.get(key);
        if (v == null) {
            throw new IllegalArgumentException("'" + at(key) + "' is missing");
        }
        return new JsonAt(v, at(key));
    }

    /** The value of {@code key}, or null when it is not there. */
    JsonAt optional(String key) {
        JsonNode v = node.get(key);
        return v == null ? null : new JsonAt(v, at(key));
    }

    /** Whether {@code key} is there. */
    boolean has(String key) {
        return node.has(key);
    }

    /** This value, which must be an object. */
    JsonAt object() {
        if (!node.isObject()) {
            throw wrong("expected an object");
        }
        return this;
    }

    /** An object's members, in the file's order. */
    Map<String, JsonAt> members() {
        object();
        Map<String, JsonAt> out = new LinkedHashMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            out.put(e.getKey(), new JsonAt(e.getValue(), at(e.getKey())));
        }
        return out;
    }

    /** A whole number under {@code key}. */
    int integer(String key) {
        JsonAt v = get(key);
        if (!v.node.canConvertToInt() || !v.node.isIntegralNumber()) {
            throw v.wrong("expected a whole number");
        }
        return v.node.intValue();
    }

    /** A count under {@code key}: a whole number, 0 or more. */
    int count(String key) {
        int v = integer(key);
        if (v < 0) {
            throw get(key).wrong(v + ", expected 0 or more");
        }
        return v;
    }

    /** A number under {@code key}; NaN for {@code null}. */
    double number(String key) {
        JsonAt v = get(key);
        if (v.node.isNull()) {
            return Double.NaN;
        }
        if (!v.node.isNumber()) {
            throw v.wrong("expected a number or null");
        }
        return v.node.doubleValue();
    }

    /** A string under {@code key}. */
    String text(String key) {
        JsonAt v = get(key);
        if (!v.node.isTextual()) {
            throw v.wrong("expected a string");
        }
        return v.node.textValue();
    }

    /** {@code true} or {@code false} under {@code key}. */
    boolean bool(String key) {
        JsonAt v = get(key);
        if (!v.node.isBoolean()) {
            throw v.wrong("expected true or false");
        }
        return v.node.booleanValue();
    }

    /** An array of numbers (nulls read as NaN) under {@code key}. */
    double[] doubles(String key) {
        JsonAt a = get(key);
        if (!a.node.isArray()) {
            throw a.wrong("expected an array of numbers");
        }
        double[] out = new double[a.node.size()];
        for (int i = 0; i < out.length; i++) {
            JsonNode v = a.node.get(i);
            if (!v.isNull() && !v.isNumber()) {
                throw a.wrong("expected an array of numbers");
            }
            out[i] = v.isNull() ? Double.NaN : v.doubleValue();
        }
        return out;
    }

    /**
     * What {@code make} builds from values read here; the constructor's own check of its ranges (the one place a range
     * is checked) told as wrong here.
     */
    <T> T built(Supplier<T> make) {
        try {
            return make.get();
        } catch (IllegalArgumentException e) {
            throw wrong(e.getMessage());
        }
    }

    /** Writes {@code v} under {@code key}: {@code null} when it is not a finite number. */
    static void number(ObjectNode n, String key, double v) {
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            n.putNull(key);
        } else {
            n.put(key, v);
        }
    }

    /** Writes {@code values} into {@code a}, {@code null} for each that is not a finite number. */
    static void numbers(ArrayNode a, double[] values) {
        for (double v : values) {
            if (Double.isNaN(v) || Double.isInfinite(v)) {
                a.addNull();
            } else {
                a.add(v);
            }
        }
    }
}
