package dev.predmon.live;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.SafetyRule;
import dev.predmon.model.LearnedModel;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * What the live view shows of one watched log: the property's light in the conventions of robot monitors (grey: no
 * data yet; green: held, no faulty prediction; yellow: warning, the run can only be a faulty scenario; red:
 * violated), the battery over the current run with the warning and the violation, the models still alive and those
 * eliminated with the reason, the last events, the lead once both happened, the run number, and the verdicts of
 * the earlier runs. A new run (or a rotated log) resets the light, the plot and the models.
 *
 * <p>Fed from the monitor's thread ({@link #event}, {@link #record}, {@link #grew}) and read from the server's
 * ({@link #snapshot}); every method holds the tile's lock, and every part has a bounded size, so a tile costs the
 * same after a million records as after ten.
 */
public final class Tile {

    static final int PLOT_POINTS = 240;
    static final int LAST_EVENTS = 12;
    static final int EARLIER_RUNS = 20;

    private static final ObjectMapper JSON = new ObjectMapper();

    private final String log;
    private final List<LearnedModel> models;
    private final Optional<SafetyRule> safety;

    private int run;
    private long runLine = 1;
    private long runRecords;
    private MonitorEvent.Warning warning;
    private MonitorEvent.Violation violation;
    private boolean noMatch;
    private final Map<String, String> eliminated = new LinkedHashMap<>();
    private final BatterySeries battery = new BatterySeries(PLOT_POINTS);
    private final Deque<JsonNode> lastEvents = new ArrayDeque<>();
    private final Deque<ObjectNode> earlier = new ArrayDeque<>();
    private int earlierOmitted;
    private long records;
    private long line;
    private Clock clock = Clock.SECONDS;
    private long grewAtMillis;

    Tile(String log, List<LearnedModel> models, Optional<SafetyRule> safety, long nowMillis) {
        this.log = log;
        this.models = List.copyOf(models);
        this.safety = safety;
        this.grewAtMillis = nowMillis;
    }

    public String log() {
        return log;
    }

    /** An event of this log's monitor, with its JSON. */
    public synchronized void event(MonitorEvent e, String json) {
        lastEvents.addLast(parse(json));
        if (lastEvents.size() > LAST_EVENTS) {
            lastEvents.removeFirst();
        }
        if (e instanceof MonitorEvent.Warning w) {
            warning = w;
        } else if (e instanceof MonitorEvent.Violation v) {
            violation = v;
        } else if (e instanceof MonitorEvent.Eliminated x) {
            eliminated.put(x.model(), "line " + x.line() + ": " + x.reason());
        } else if (e instanceof MonitorEvent.NoMatch) {
            noMatch = true;
        } else if (e instanceof MonitorEvent.RunStarted r) {
            keepVerdict();
            startRun(r.run(), r.line());
        } else if (e instanceof MonitorEvent.Restarted) {
            // A rotated log goes on in a new run, as the monitor numbers it; the runs before it stay on the tile.
            boolean begun = records > 0;
            if (begun) {
                keepVerdict();
            }
            records = 0;
            startRun(begun ? run + 1 : run, 1);
        }
    }

    /** The run shown so far becomes an earlier run (the last {@value #EARLIER_RUNS} are kept). */
    private void keepVerdict() {
        earlier.addLast(verdict());
        if (earlier.size() > EARLIER_RUNS) {
            earlier.removeFirst();
            earlierOmitted++;
        }
    }

    private void startRun(int number, long first) {
        run = number;
        runLine = first;
        runRecords = 0;
        warning = null;
        violation = null;
        noMatch = false;
        eliminated.clear();
        battery.clear();
    }

    /** A record of the log, after the monitor took it (so a new run has begun already if it begins one). */
    public synchronized void record(LogRecord r) {
        records++;
        runRecords++;
        line = r.line();
        clock = r.clock();
        if (safety.isPresent()) {
            double v = safety.get().valueOf(r);
            if (!Double.isNaN(v)) {
                battery.add(r.time(), v);
            }
        }
    }

    /** The log grew (or was rotated) at this time. */
    public synchronized void grew(long nowMillis) {
        grewAtMillis = nowMillis;
    }

    /**
     * The light: red once the property is violated in this run, else yellow once warned, else green once there is
     * data (a reading of the property; any record where there is no property), else grey.
     */
    public synchronized String light() {
        if (violation != null) {
            return "red";
        }
        if (warning != null) {
            return "yellow";
        }
        boolean data = safety.isPresent() ? !battery.isEmpty() : runRecords > 0;
        return data ? "green" : "grey";
    }

    /** The tile as {@code /status} gives it; {@code stale} when the log has not grown for {@code staleMillis}. */
    public synchronized ObjectNode snapshot(long nowMillis, long staleMillis) {
        ObjectNode o = JSON.createObjectNode();
        o.put("log", log);
        o.put("light", light());
        long quiet = Math.max(0, nowMillis - grewAtMillis);
        o.put("stale", quiet >= staleMillis);
        o.put("quietSeconds", quiet / 1000.0);
        o.put("run", run);
        o.put("runLine", runLine);
        o.put("records", records);
        o.put("line", line);
        o.put("unit", clock.unit());
        o.put("property", safety.map(SafetyRule::name).orElse(null));
        if (safety.isPresent()) {
            o.put("threshold", safety.get().below());
        }
        putNumber(o, "battery", battery.last());
        o.set("warning", warning == null ? null : warningNode(warning));
        o.set("violation", violation == null ? null : violationNode(violation));
        putNumber(o, "lead", warning != null && violation != null ? violation.time() - warning.time() : Double.NaN);
        o.put("noMatch", noMatch);
        ArrayNode ms = o.putArray("models");
        for (LearnedModel m : models) {
            ObjectNode x = ms.addObject();
            x.put("model", m.id());
            x.put("scenario", m.scenario());
            x.put("faulty", m.faulty());
            String reason = eliminated.get(m.id());
            x.put("alive", reason == null);
            x.put("reason", reason);
        }
        ArrayNode points = o.putArray("series");
        for (double[] p : battery.points()) {
            points.addArray().add(p[0]).add(p[1]);
        }
        ArrayNode events = o.putArray("events");
        lastEvents.forEach(events::add);
        ArrayNode runs = o.putArray("earlierRuns");
        earlier.forEach(runs::add);
        o.put("earlierRunsOmitted", earlierOmitted);
        return o;
    }

    private ObjectNode verdict() {
        ObjectNode o = JSON.createObjectNode();
        o.put("run", run);
        o.put("line", runLine);
        o.put("warning", warning != null);
        o.put("violation", violation != null);
        putNumber(o, "lead", warning != null && violation != null ? violation.time() - warning.time() : Double.NaN);
        o.put("noMatch", noMatch);
        o.put("light", light());
        return o;
    }

    private static JsonNode warningNode(MonitorEvent.Warning w) {
        ObjectNode o = JSON.createObjectNode();
        o.put("time", w.time());
        o.put("line", w.line());
        if (w.battery() != null) {
            o.put("battery", w.battery());
        }
        ArrayNode s = o.putArray("scenarios");
        w.scenarios().forEach(s::add);
        return o;
    }

    private static JsonNode violationNode(MonitorEvent.Violation v) {
        ObjectNode o = JSON.createObjectNode();
        o.put("time", v.time());
        o.put("line", v.line());
        o.put("battery", v.value());
        return o;
    }

    private static JsonNode parse(String json) {
        try {
            return JSON.readTree(json);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException("an event's JSON does not parse: " + json, e);
        }
    }

    private static void putNumber(ObjectNode o, String key, double value) {
        if (Double.isNaN(value)) {
            o.putNull(key);
        } else {
            o.put(key, value);
        }
    }
}
