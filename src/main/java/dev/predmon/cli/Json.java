package dev.predmon.cli;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.ObjectWriter;

/**
 * The JSON writer of command documents. Commands print records (their fields in declaration order), either one
 * object per line ({@code classify --json}, {@code verify --json}) or one indented document ({@code evaluate --json},
 * {@code explain --json}). Watch's events are {@link dev.predmon.event.EventJson}'s.
 */
final class Json {

    private static final ObjectMapper MAPPER = new ObjectMapper();
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

    private static String write(ObjectWriter writer, Object value) {
        try {
            return writer.writeValueAsString(value);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("records of plain values always serialise", e);
        }
    }
}
