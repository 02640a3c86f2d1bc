package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.model.LearnedModel;
import dev.predmon.monitor.MonitorEvent;

import java.util.List;
import java.util.Map;

/** The parts of a tile's {@code /status} JSON that are the same whatever the tile: events, models, numbers. */
final class TileJson {

    static final ObjectMapper JSON = new ObjectMapper();

    private TileJson() {
    }

    /**
     * The warning: when, where, the value ({@code battery} too, its older name), the faulty scenarios left (none for a
     * forecast-rule warning), the rule and the clause that warned, its reason in an operator's words, and the forecast
     * at the warning as the event's JSON gave it (or null).
     */
    static ObjectNode warning(MonitorEvent.Warning w, JsonNode event) {
        ObjectNode o = JSON.createObjectNode();
        o.put("time", w.time());
        o.put("line", w.line());
        if (w.value() != null) {
            o.put("value", w.value());
            o.put("battery", w.value());
        }
        ArrayNode s = o.putArray("scenarios");
        w.scenarios().forEach(s::add);
        o.put("rule", w.rule().id());
        o.put("clause", w.clause().id());
        o.put("reason", w.reason());
        o.set("forecast", forecastOf(event));
        return o;
    }

    static ObjectNode violation(MonitorEvent.Violation v) {
        ObjectNode o = JSON.createObjectNode();
        o.put("time", v.time());
        o.put("line", v.line());
        o.put("value", v.value());
        o.put("battery", v.value());
        return o;
    }

    /** One moment of a run's history: a warning, a violation, a recovery. */
    static ObjectNode moment(String what, double time, long line, double value) {
        ObjectNode o = JSON.createObjectNode();
        o.put("what", what);
        o.put("time", time);
        o.put("line", line);
        number(o, "value", value);
        return o;
    }

    /** Every model: alive, or eliminated with {@code line N: reason}. */
    static ArrayNode models(List<LearnedModel> models, Map<String, String> eliminated) {
        ArrayNode ms = JSON.createArrayNode();
        for (LearnedModel m : models) {
            ObjectNode x = ms.addObject();
            x.put("model", m.id());
            x.put("scenario", m.scenario());
            x.put("faulty", m.faulty());
            String reason = eliminated.get(m.id());
            x.put("alive", reason == null);
            x.put("reason", reason);
        }
        return ms;
    }

    /** The {@code forecast} object of an event's JSON (the fields {@code watch --json} prints), or null. */
    static JsonNode forecastOf(JsonNode event) {
        JsonNode f = event == null ? null : event.get("forecast");
        return f == null || f.isNull() ? null : f;
    }

    static void number(ObjectNode o, String key, double value) {
        if (Double.isNaN(value)) {
            o.putNull(key);
        } else {
            o.put(key, value);
        }
    }
}
