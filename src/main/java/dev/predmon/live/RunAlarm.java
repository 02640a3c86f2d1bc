package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.monitor.MonitorEvent;

import java.util.ArrayDeque;
import java.util.Deque;

import static dev.predmon.live.TileJson.number;

/**
 * The alarms of the run a tile shows, as the monitor decided them: the run's warning and violation, whether one of
 * them is up now or the run recovered from it ({@link MonitorEvent.Recovered}), the run's moments (warned, violated,
 * recovered; they stay after a recovery), and whether the recommended action is under way. Bounded: the last
 * {@value #HISTORY} moments.
 */
final class RunAlarm {

    static final int HISTORY = 8;

    private MonitorEvent.Warning warning;
    private JsonNode warningJson;
    private MonitorEvent.Violation violation;
    private boolean warned;
    private boolean violated;
    private MonitorEvent.Recovered recovery;
    private MonitorEvent.UnderWay underWay;
    private final Deque<ObjectNode> history = new ArrayDeque<>();

    /** Takes an event of the run; whether it was one of the alarm's. */
    boolean event(MonitorEvent e, JsonNode node) {
        if (e instanceof MonitorEvent.Warning w) {
            warning = w;
            warningJson = node;
            warned = true;
            recovery = null;
            note(TileJson.moment("warning", w.time(), w.line(), w.value() == null ? Double.NaN : w.value()));
        } else if (e instanceof MonitorEvent.Violation v && v.forecast()) { // the light follows the forecast's property
            note(TileJson.moment(violation == null ? "violation" : "violated again", v.time(), v.line(), v.value()));
            violation = violation == null ? v : violation; // the lead is the first violation's
            violated = true;
            recovery = null;
        } else if (e instanceof MonitorEvent.Recovered r) {
            recovery = r;
            warned = false;
            violated = false;
            note(TileJson.moment("recovered", r.time(), r.line(), r.value()));
        } else if (e instanceof MonitorEvent.UnderWay u) {
            underWay = u.underWay() ? u : null;
        } else {
            return false;
        }
        return true;
    }

    private void note(ObjectNode moment) {
        history.addLast(moment);
        if (history.size() > HISTORY) {
            history.removeFirst();
        }
    }

    /** A new run: nothing happened yet. */
    void reset() {
        warning = null;
        warningJson = null;
        violation = null;
        warned = false;
        violated = false;
        recovery = null;
        underWay = null;
        history.clear();
    }

    /** Whether the property is violated now. */
    boolean violatedNow() {
        return violated;
    }

    /** Whether a warning is up now. */
    boolean warnedNow() {
        return warned && !violated;
    }

    /** Whether the run recovered from its last alarm and none is up. */
    boolean recovered() {
        return recovery != null;
    }

    boolean warned() {
        return warning != null;
    }

    boolean violatedEver() {
        return violation != null;
    }

    /** The lead: the first violation's time minus the warning's, NaN until both happened. */
    double lead() {
        return warning != null && violation != null ? violation.time() - warning.time() : Double.NaN;
    }

    /** The alarm's fields of {@code /status}. */
    void snapshot(ObjectNode o) {
        o.set("warning", warning == null ? null : TileJson.warning(warning, warningJson));
        o.set("violation", violation == null ? null : TileJson.violation(violation));
        o.put("recovered", recovery != null);
        if (recovery == null) {
            o.putNull("recovery");
        } else {
            ObjectNode r = o.putObject("recovery");
            r.put("time", recovery.time());
            r.put("line", recovery.line());
            r.put("cause", recovery.cause());
            r.put("value", recovery.value());
            r.put("battery", recovery.value());
            r.put("reason", recovery.reason());
        }
        if (underWay == null) {
            o.putNull("underWay");
        } else {
            ObjectNode u = o.putObject("underWay");
            u.put("since", underWay.time());
            u.put("line", underWay.line());
            u.put("by", underWay.by());
        }
        number(o, "lead", lead());
        ArrayNode moments = o.putArray("history");
        history.forEach(moments::add);
    }

    /** The alarm's fields of an earlier run's verdict. */
    void verdict(ObjectNode o) {
        o.put("warning", warning != null);
        o.put("violation", violation != null);
        number(o, "lead", lead());
        o.put("recovered", recovery != null);
    }
}
