package dev.predmon.rosbridge;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.rosbag.ByteArrays;

import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Base64;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A rosbridge message's JSON ({@code "msg"} of a {@code publish}) as the fields a recording's reader gives
 * ({@link dev.predmon.rosbag.BagMessage}): integers as {@code Long} (a {@code uint64} above {@code Long.MAX_VALUE}
 * keeps its bits), other numbers as {@code Double}, {@code NaN} and infinities (which rosbridge writes as bare
 * words) as such, a {@code null} float as NaN; byte arrays, which rosbridge sends as base64 text, as lists of their
 * bytes for the types predmon bundles.
 */
final class JsonMessages {

    private static final Map<String, List<String>> BYTES = new ConcurrentHashMap<>();

    private JsonMessages() {
    }

    /** The fields of {@code msg}, a message of {@code type} (null when unknown). */
    static Map<String, Object> fields(JsonNode msg, String type) {
        List<String> bytes = type == null ? List.of() : BYTES.computeIfAbsent(type, ByteArrays::paths);
        Object v = value(msg, "", bytes);
        if (v instanceof Map<?, ?> m) {
            @SuppressWarnings("unchecked")
            Map<String, Object> fields = (Map<String, Object>) m;
            return fields;
        }
        throw new IllegalArgumentException("the message is " + msg.getNodeType().toString().toLowerCase(
                java.util.Locale.ROOT) + ", not an object");
    }

    private static Object value(JsonNode n, String path, List<String> bytes) {
        if (n.isObject()) {
            Map<String, Object> m = new LinkedHashMap<>();
            for (Iterator<Map.Entry<String, JsonNode>> it = n.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> e = it.next();
                String p = path.isEmpty() ? e.getKey() : path + "." + e.getKey();
                m.put(e.getKey(), value(e.getValue(), p, bytes));
            }
            return m;
        }
        if (n.isArray()) {
            List<Object> l = new ArrayList<>(n.size());
            n.forEach(e -> l.add(value(e, path, bytes)));
            return l;
        }
        if (n.isTextual() && bytes.contains(path)) {
            try {
                byte[] b = Base64.getDecoder().decode(n.asText());
                List<Object> l = new ArrayList<>(b.length);
                for (byte x : b) {
                    l.add((long) (x & 0xff));
                }
                return l;
            } catch (IllegalArgumentException notBase64) {
                return n.asText();
            }
        }
        if (n.isIntegralNumber()) {
            BigInteger i = n.bigIntegerValue();
            return i.longValue(); // a uint64 above Long.MAX_VALUE keeps its bits, as a reader's does
        }
        if (n.isNumber()) {
            return n.doubleValue();
        }
        if (n.isBoolean()) {
            return n.booleanValue();
        }
        if (n.isTextual()) {
            return n.asText();
        }
        return n.isNull() ? Double.NaN : null; // rosbridge writes a NaN float as null with some JSON encoders
    }
}
