package dev.predmon.rosbag;

import com.fasterxml.jackson.core.json.JsonReadFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;

import java.io.IOException;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/** The expected messages the Python scripts write as JSON, and a field-by-field comparison with decoded values. */
final class JsonValues {

    static final ObjectMapper JSON = JsonMapper.builder().enable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS).build();

    private JsonValues() {
    }

    static JsonNode parse(String text) throws IOException {
        return JSON.readTree(text);
    }

    /** Asserts that {@code actual} (a decoded value) is {@code expected}, naming the field path where not. */
    static void assertValue(JsonNode expected, Object actual, String path) {
        if (expected.isObject()) {
            if (!(actual instanceof Map<?, ?> m)) {
                fail(path + ": expected a message, decoded " + actual);
                return;
            }
            List<String> names = new ArrayList<>();
            expected.fieldNames().forEachRemaining(names::add);
            assertEquals(names, new ArrayList<>(m.keySet().stream().map(String::valueOf).toList()),
                    path + ": the fields, in order");
            for (String n : names) {
                assertValue(expected.get(n), m.get(n), path + "." + n);
            }
        } else if (expected.isArray()) {
            if (!(actual instanceof List<?> l)) {
                fail(path + ": expected an array, decoded " + actual);
                return;
            }
            assertEquals(expected.size(), l.size(), path + ": the number of elements");
            Iterator<JsonNode> it = expected.elements();
            for (int i = 0; it.hasNext(); i++) {
                assertValue(it.next(), l.get(i), path + "[" + i + "]");
            }
        } else if (expected.isIntegralNumber()) {
            if (actual instanceof Long v) {
                BigInteger want = expected.bigIntegerValue();
                BigInteger got = want.signum() >= 0 && want.bitLength() == 64
                        ? new BigInteger(Long.toUnsignedString(v)) : BigInteger.valueOf(v);
                assertEquals(want, got, path);
            } else if (actual instanceof Double d) {
                assertEquals(expected.doubleValue(), d, 0.0, path);
            } else {
                fail(path + ": expected the number " + expected + ", decoded " + actual);
            }
        } else if (expected.isNumber()) {
            assertTrue(actual instanceof Double, path + ": expected a Double, decoded " + actual);
            double want = expected.doubleValue();
            if (Double.isNaN(want)) {
                assertTrue(Double.isNaN((Double) actual), path + ": expected NaN, decoded " + actual);
            } else {
                assertEquals(want, (Double) actual, 0.0, path);
            }
        } else if (expected.isBoolean()) {
            assertEquals(expected.booleanValue(), actual, path);
        } else if (expected.isTextual()) {
            assertEquals(expected.textValue(), actual, path);
        } else {
            fail(path + ": unexpected JSON " + expected);
        }
    }

    /** A JSON value as the plain Java values a writer takes. */
    static Object plain(JsonNode n) {
        if (n.isObject()) {
            Map<String, Object> m = new LinkedHashMap<>();
            n.fields().forEachRemaining(e -> m.put(e.getKey(), plain(e.getValue())));
            return m;
        }
        if (n.isArray()) {
            List<Object> l = new ArrayList<>();
            n.elements().forEachRemaining(e -> l.add(plain(e)));
            return l;
        }
        if (n.isIntegralNumber()) {
            return n.bigIntegerValue().longValue();
        }
        if (n.isNumber()) {
            return n.doubleValue();
        }
        if (n.isBoolean()) {
            return n.booleanValue();
        }
        return n.textValue();
    }
}
