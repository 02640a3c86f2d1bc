package dev.predmon.abstraction.file;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionSpec.DropSpec;
import dev.predmon.abstraction.file.AbstractionSpec.RangeSpec;
import dev.predmon.abstraction.file.AbstractionSpec.ReplySpec;
import dev.predmon.abstraction.file.AbstractionSpec.RuleSpec;
import dev.predmon.abstraction.file.AbstractionSpec.RunsSpec;
import dev.predmon.abstraction.file.AbstractionSpec.SafetySpec;
import dev.predmon.abstraction.file.AbstractionSpec.UnderWaySpec;
import dev.predmon.abstraction.file.AbstractionSpec.WarningSpec;

import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The canonical JSON of an {@link AbstractionSpec}, the text {@link Abstraction#fingerprint()} hashes and
 * {@code models/abstraction.json} holds. Model directories on disk carry fingerprints of it, so it must stay
 * byte for byte what Jackson's data binding wrote before (a test compares the two): one line, keys in
 * alphabetical order, absent (null) keys left out, map entries by key, {@code equals} for
 * {@link ReplySpec#values()}, and numbers, strings and escapes as jackson-core's generator writes them
 * ({@code 20.0} for a double, {@code "NaN"} for a NaN). Written here with that generator, so that no
 * {@code ObjectMapper} is built at start-up.
 */
final class SpecWriter {

    private SpecWriter() {
    }

    /** The canonical JSON of {@code spec}. */
    static String canonical(AbstractionSpec spec) {
        return canonical(spec, null);
    }

    /**
     * The canonical JSON of {@code spec} with a {@code properties} list.
     *
     * @param properties the list's canonical JSON ({@link #properties}), or null for none
     */
    static String canonical(AbstractionSpec spec, String properties) {
        return canonical(spec, properties, null);
    }

    /**
     * The canonical JSON of {@code spec} with a {@code properties} list and a {@code ros2} section.
     *
     * @param ros2 the section's canonical JSON ({@link #properties}, which writes any tree so), or null for none
     */
    static String canonical(AbstractionSpec spec, String properties, String ros2) {
        StringWriter out = new StringWriter();
        try (JsonGenerator g = LocatedJson.FACTORY.createGenerator(out)) {
            spec(g, spec, properties, ros2);
        } catch (IOException e) {
            throw new UncheckedIOException("writing to a string cannot fail", e);
        }
        return out.toString();
    }

    // Each record's keys below are written in alphabetical order.

    private static void spec(JsonGenerator g, AbstractionSpec s, String properties, String ros2) throws IOException {
        g.writeStartObject();
        string(g, "description", s.description());
        if (s.drop() != null) {
            g.writeArrayFieldStart("drop");
            for (DropSpec d : s.drop()) {
                drop(g, d);
            }
            g.writeEndArray();
        }
        if (s.locations() != null) {
            g.writeObjectFieldStart("locations");
            for (Map.Entry<String, String> e : new TreeMap<>(s.locations()).entrySet()) {
                g.writeFieldName(e.getKey());
                if (e.getValue() == null) {
                    g.writeNull();
                } else {
                    g.writeString(e.getValue());
                }
            }
            g.writeEndObject();
        }
        string(g, "name", s.name());
        if (properties != null) {
            g.writeFieldName("properties");
            g.writeRawValue(properties);
        }
        if (ros2 != null) {
            g.writeFieldName("ros2");
            g.writeRawValue(ros2);
        }
        if (s.rules() != null) {
            g.writeArrayFieldStart("rules");
            for (RuleSpec r : s.rules()) {
                rule(g, r);
            }
            g.writeEndArray();
        }
        if (s.runs() != null) {
            g.writeFieldName("runs");
            runs(g, s.runs());
        }
        if (s.safety() != null) {
            g.writeFieldName("safety");
            safety(g, s.safety());
        }
        if (s.warning() != null) {
            g.writeFieldName("warning");
            warning(g, s.warning());
        }
        g.writeEndObject();
    }

    private static void drop(JsonGenerator g, DropSpec d) throws IOException {
        if (d == null) {
            g.writeNull();
            return;
        }
        g.writeStartObject();
        string(g, "command", d.command());
        string(g, "description", d.description());
        string(g, "from", d.from());
        string(g, "kind", d.kind());
        string(g, "protocol", d.protocol());
        string(g, "to", d.to());
        g.writeEndObject();
    }

    private static void rule(JsonGenerator g, RuleSpec r) throws IOException {
        if (r == null) {
            g.writeNull();
            return;
        }
        g.writeStartObject();
        bool(g, "carry", r.carry());
        string(g, "client", r.client());
        string(g, "command", r.command());
        bool(g, "continuous", r.continuous());
        string(g, "description", r.description());
        number(g, "hysteresis", r.hysteresis());
        string(g, "input", r.input());
        string(g, "protocol", r.protocol());
        if (r.replies() != null) {
            g.writeArrayFieldStart("replies");
            for (ReplySpec p : r.replies()) {
                reply(g, p);
            }
            g.writeEndArray();
        }
        g.writeEndObject();
    }

    private static void reply(JsonGenerator g, ReplySpec p) throws IOException {
        if (p == null) {
            g.writeNull();
            return;
        }
        g.writeStartObject();
        bool(g, "any", p.any());
        strings(g, "equals", p.values());
        if (p.range() != null) {
            g.writeFieldName("range");
            range(g, p.range());
        }
        string(g, "symbol", p.symbol());
        g.writeEndObject();
    }

    private static void range(JsonGenerator g, RangeSpec r) throws IOException {
        g.writeStartObject();
        number(g, "above", r.above());
        number(g, "atLeast", r.atLeast());
        number(g, "atMost", r.atMost());
        number(g, "below", r.below());
        g.writeEndObject();
    }

    private static void runs(JsonGenerator g, RunsSpec r) throws IOException {
        g.writeStartObject();
        string(g, "description", r.description());
        number(g, "silence", r.silence());
        bool(g, "tickRestart", r.tickRestart());
        g.writeEndObject();
    }

    private static void safety(JsonGenerator g, SafetySpec s) throws IOException {
        g.writeStartObject();
        string(g, "action", s.action());
        number(g, "below", s.below());
        string(g, "command", s.command());
        string(g, "from", s.from());
        string(g, "name", s.name());
        string(g, "protocol", s.protocol());
        string(g, "to", s.to());
        if (s.underWay() != null) {
            g.writeArrayFieldStart("underWay");
            for (UnderWaySpec u : s.underWay()) {
                if (u == null) {
                    g.writeNull();
                    continue;
                }
                g.writeStartObject();
                string(g, "argument", u.argument());
                string(g, "command", u.command());
                string(g, "protocol", u.protocol());
                string(g, "skill", u.skill());
                g.writeEndObject();
            }
            g.writeEndArray();
        }
        g.writeEndObject();
    }

    private static void warning(JsonGenerator g, WarningSpec w) throws IOException {
        g.writeStartObject();
        if (w.confirm() != null) {
            g.writeNumberField("confirm", w.confirm());
        }
        string(g, "description", w.description());
        g.writeEndObject();
    }

    private static void strings(JsonGenerator g, String name, List<String> values) throws IOException {
        if (values == null) {
            return;
        }
        g.writeArrayFieldStart(name);
        for (String v : values) {
            if (v == null) {
                g.writeNull();
            } else {
                g.writeString(v);
            }
        }
        g.writeEndArray();
    }

    private static void string(JsonGenerator g, String name, String value) throws IOException {
        if (value != null) {
            g.writeStringField(name, value);
        }
    }

    private static void number(JsonGenerator g, String name, Double value) throws IOException {
        if (value != null) {
            g.writeNumberField(name, value.doubleValue());
        }
    }

    private static void bool(JsonGenerator g, String name, Boolean value) throws IOException {
        if (value != null) {
            g.writeBooleanField(name, value);
        }
    }

    /** The canonical form of a {@code properties} list: keys sorted at every level, numbers as doubles, one line. */
    static String properties(JsonNode list) {
        StringWriter out = new StringWriter();
        try (JsonGenerator g = LocatedJson.FACTORY.createGenerator(out)) {
            write(g, list);
        } catch (IOException e) {
            throw new UncheckedIOException("writing to a string cannot fail", e);
        }
        return out.toString();
    }

    private static void write(JsonGenerator g, JsonNode n) throws IOException {
        if (n.isObject()) {
            g.writeStartObject();
            Map<String, JsonNode> sorted = new TreeMap<>();
            n.fields().forEachRemaining(e -> sorted.put(e.getKey(), e.getValue()));
            for (Map.Entry<String, JsonNode> e : sorted.entrySet()) {
                g.writeFieldName(e.getKey());
                write(g, e.getValue());
            }
            g.writeEndObject();
        } else if (n.isArray()) {
            g.writeStartArray();
            for (JsonNode e : n) {
                write(g, e);
            }
            g.writeEndArray();
        } else if (n.isTextual()) {
            g.writeString(n.textValue());
        } else if (n.isNumber()) {
            // every number a double, as the rest of the canonical form writes them (10 is 10.0): one reading of it
            g.writeNumber(n.doubleValue());
        } else if (n.isBoolean()) {
            g.writeBoolean(n.booleanValue());
        } else {
            g.writeNull();
        }
    }
}
