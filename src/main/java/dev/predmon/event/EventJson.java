package dev.predmon.event;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.ObjectWriter;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.forecast.Survival;
import dev.predmon.monitor.MonitorEvent;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The JSON object of each monitor event: {@code "event"} first ({@code warning}, {@code violation}, ...), then
 * {@code "log"} when the event names its log, the event's fields, and {@code "wallTime"} last (when it was sent, UTC).
 * The records below fix the fields and their order; {@link MonitorEvent.Unmapped} has none (it goes to stderr with
 * the parse problems). Watch's own events ({@code heartbeat}, {@code end}) are records of the same shape, written by
 * {@link #stamped}.
 */
public final class EventJson {

    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final ObjectWriter LINE = MAPPER.writer();
    private static final DateTimeFormatter WALL_TIME = DateTimeFormatter.ofPattern("uuuu-MM-dd'T'HH:mm:ss.SSS'Z'",
            Locale.ROOT).withZone(ZoneOffset.UTC);

    private EventJson() {
    }

    /**
     * The JSON object of {@code e} of {@code log} ({@code "log"} right after {@code "event"}, or untagged if null),
     * sent at wall-clock time {@code at}.
     *
     * @throws IllegalArgumentException for {@link MonitorEvent.Unmapped}, which is no JSON event
     */
    public static ObjectNode of(MonitorEvent e, String log, Instant at) {
        return stamped(record(e), log, at);
    }

    private static Object record(MonitorEvent e) {
        if (e instanceof MonitorEvent.Warning w) {
            return new WarningJson("warning", w.time(), w.clock().unit(), w.line(), w.run(), w.property(),
                    w.scenario(), w.scenarios(), w.value(), w.value(), w.pairs(), w.rule().id(), w.clause().id(),
                    w.reason(),
                    ForecastJson.of(w.forecast()), DeadlineJson.of(w.deadline()));
        } else if (e instanceof MonitorEvent.ForecastChanged f) {
            return new ForecastEventJson("forecast", f.time(), f.clock().unit(), f.line(), f.run(),
                    ForecastJson.of(f.forecast()), f.property(), DeadlineJson.of(f.deadline()));
        } else if (e instanceof MonitorEvent.Violation v) {
            return new ViolationJson("violation", v.time(), v.clock().unit(), v.line(), v.run(), v.property(),
                    v.name(), v.value(), v.forecast() ? v.value() : null, v.before(), v.what());
        } else if (e instanceof MonitorEvent.Eliminated x) {
            return new EliminatedJson("eliminated", x.time(), x.clock().unit(), x.line(), x.run(), x.model(),
                    x.scenario(), x.faulty(), x.reason());
        } else if (e instanceof MonitorEvent.NoMatch n) {
            return new NoMatchJson("no-match", n.time(), n.clock().unit(), n.line(), n.run());
        } else if (e instanceof MonitorEvent.RunStarted r) {
            return new RunJson("run", r.run(), r.time(), r.clock().unit(), r.line());
        } else if (e instanceof MonitorEvent.Restarted r) {
            return new RestartedJson("restarted", r.reason());
        } else if (e instanceof MonitorEvent.Recovered r) {
            Double value = Double.isNaN(r.value()) ? null : r.value();
            return new RecoveredJson("recovered", r.time(), r.clock().unit(), r.line(), r.run(), r.cause(), value,
                    value, r.reason(), r.property());
        } else if (e instanceof MonitorEvent.UnderWay u) {
            return new UnderWayJson("under-way", u.time(), u.clock().unit(), u.line(), u.run(), u.by(), u.underWay());
        }
        throw new IllegalArgumentException("not a JSON event: " + e);
    }

    /**
     * {@code value} (a record whose first field is {@code "event"}) as a JSON object, with {@code "log": log} right
     * after {@code "event"} unless {@code log} is null, and {@code "wallTime"} last ({@link #wallTime}).
     */
    public static ObjectNode stamped(Object value, String log, Instant at) {
        ObjectNode plain = MAPPER.valueToTree(value);
        ObjectNode node = log == null ? plain : tagged(plain, log);
        node.put("wallTime", wallTime(at));
        return node;
    }

    private static ObjectNode tagged(ObjectNode plain, String log) {
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

    /** One line of JSON. */
    public static String line(JsonNode node) {
        try {
            return LINE.writeValueAsString(node);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a tree of plain values always serialises", e);
        }
    }

    /** A wall-clock time as events carry it: ISO 8601 in UTC to the millisecond, {@code 2026-11-25T17:40:01.123Z}. */
    public static String wallTime(Instant at) {
        return WALL_TIME.format(at);
    }

    /**
     * A warning: {@code property} the id of the property whose violation is predicted, {@code value} its value at the
     * warning (null before any reading, and for a bounded response's deadline, which has none), {@code battery} the
     * same under its older name, kept for existing scripts.
     */
    record WarningJson(String event, double time, String unit, long line, int run, String property,
                       String scenario, List<String> scenarios, Double value, Double battery, long pairs, String rule,
                       String clause, String reason, ForecastJson forecast, DeadlineJson deadline) {
    }

    /**
     * A deadline forecast: {@code probability} of a miss (null when the obligation is past every training one:
     * {@code novel}), {@code timeLeft} before the deadline in its unit, {@code atRisk} training obligations pending
     * as long, {@code longer} of them still pending at the deadline.
     */
    record DeadlineJson(Double probability, double timeLeft, int atRisk, int longer, boolean novel) {
        static DeadlineJson of(Survival.Estimate e) {
            return e == null ? null : new DeadlineJson(e.novel() ? null : e.probability(), e.timeLeft(), e.atRisk(),
                    e.longer(), e.novel());
        }
    }

    /**
     * A recovery: {@code value} the property's value (null for a property without one), {@code battery} the same under
     * its older name, {@code property} its id.
     */
    record RecoveredJson(String event, double time, String unit, long line, int run, String cause, Double value,
                         Double battery, String reason, String property) {
    }

    record UnderWayJson(String event, double time, String unit, long line, int run, String by, boolean underWay) {
    }

    record ForecastEventJson(String event, double time, String unit, long line, int run, ForecastJson forecast,
                             String property,
                             DeadlineJson deadline) {
    }

    /**
     * A property's violation: {@code property} its id, {@code name} its words, {@code value} the violating value of a
     * bound (null for an event), {@code battery} the same for the forecast's property only (its older name, kept for
     * existing scripts), {@code what} in words.
     */
    record ViolationJson(String event, double time, String unit, long line, int run, String property, String name,
                         Double value, Double battery, Double before, String what) {
    }

    record EliminatedJson(String event, double time, String unit, long line, int run, String model, String scenario,
                          boolean faulty, String reason) {
    }

    record NoMatchJson(String event, double time, String unit, long line, int run) {
    }

    record RunJson(String event, int run, double time, String unit, long line) {
    }

    record RestartedJson(String event, String reason) {
    }
}
