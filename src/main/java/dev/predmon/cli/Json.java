package dev.predmon.cli;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.ObjectWriter;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Iterator;
import java.util.Locale;
import java.util.Map;

/**
 * The one JSON writer of command output. Commands print records (their fields in declaration order), either one
 * object per line ({@code watch --json} events, {@code classify --json}) or one indented document
 * ({@code evaluate --json}, {@code explain --json}).
 */
final class Json {

    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final DateTimeFormatter WALL_TIME = DateTimeFormatter.ofPattern("uuuu-MM-dd'T'HH:mm:ss.SSS'Z'",
            Locale.ROOT).withZone(ZoneOffset.UTC);
    private static final ObjectWriter LINE = MAPPER.writer();
    private static final ObjectWriter DOCUMENT = MAPPER.writerWithDefaultPrettyPrinter();

    private Json() {
    }

    /** One line of JSON. */
    static String line(Object value) {
        return write(LINE, value);
    }

    /** An indented JSON document. */
    static String document(Object value) {
        return write(DOCUMENT, value);
    }

    /** {@code value} as a JSON object with {@code "log": log} right after its first field ({@code "event"}). */
    static Object tagged(Object value, String log) {
        ObjectNode plain = MAPPER.valueToTree(value);
        ObjectNode tagged = MAPPER.createObjectNode();
        Iterator<Map.Entry<String, JsonNode>> fields = plain.fields();
        boolean first = true;
        while (fields.hasNext()) {
            Map.Entry<String, JsonNode> f = fields.next();
            tagged.set(f.getKey(), f.getValue());
            if (first) {
                tagged.put("log", log);
                first = false;
            }
        }
        return tagged;
    }

    /**
     * {@code value} as a JSON object, with {@code "log": log} right after {@code "event"} unless {@code log} is null,
     * and {@code "wallTime"} last: when it was written, in UTC ({@link #wallTime}).
     */
    static Object stamped(Object value, String log, Instant at) {
        ObjectNode node = log == null ? MAPPER.valueToTree(value) : (ObjectNode) tagged(value, log);
        node.put("wallTime", wallTime(at));
        return node;
    }

    /** A wall-clock time as events carry it: ISO 8601 in UTC to the millisecond, {@code 2026-11-25T17:40:01.123Z}. */
    static String wallTime(Instant at) {
        return WALL_TIME.format(at);
    }

    private static String write(ObjectWriter writer, Object value) {
        try {
            return writer.writeValueAsString(value);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("records of plain values always serialise", e);
        }
    }
}
