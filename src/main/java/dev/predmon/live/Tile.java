package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.event.LogEvent;
import dev.predmon.forecast.Forecast;
import dev.predmon.model.LearnedModel;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PropertyStatus;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyView;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import static dev.predmon.live.TileJson.JSON;
import static dev.predmon.live.TileJson.number;

/**
 * What the live view shows of one watched log: its robot's {@link TileState} (waiting, ok, unknown, warning,
 * violation, ended) with its light, the forecast (probability and time to the violation, with what it rests on), the
 * warning's reason and the property's recommended action, its value over the current run with the warning and the
 * violation, this run's history (a violation stays in it after the property holds again), the models still alive and
 * those eliminated with the reason, the last events, the lead once both happened, the run number, and the verdicts of
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

    private final String log;
    private final String name;
    private final List<LearnedModel> models;
    private final Optional<Bound> safety;
    /** The headline property's position among the checked ones, once known. */
    private int index = -1;

    private int run;
    private long runLine = 1;
    private long runRecords;
    private final RunAlarm alarm = new RunAlarm();
    private final PropertyLights lights;
    private String noVerdict;
    private boolean noMatch;
    private long noMatchLine;
    private Forecast forecast;
    private JsonNode forecastJson;
    private final RunRest rest = new RunRest();
    private final Map<String, String> eliminated = new LinkedHashMap<>();
    private final ValueSeries values = new ValueSeries(PLOT_POINTS);
    private final Deque<JsonNode> lastEvents = new ArrayDeque<>();
    private final Deque<ObjectNode> earlier = new ArrayDeque<>();
    private int earlierOmitted;
    private long records;
    private long line;
    private Clock clock = Clock.SECONDS;
    private long grewAtMillis;

    Tile(String log, String name, List<LearnedModel> models, Optional<Bound> safety, List<Property> properties,
         long nowMillis) {
        this.log = log;
        this.name = name;
        this.models = List.copyOf(models);
        this.safety = safety;
        this.lights = new PropertyLights(properties, safety.map(Bound::id).orElse(null));
        this.grewAtMillis = nowMillis;
    }

    public String log() {
        return log;
    }

    /** The robot's name. */
    public String name() {
        return name;
    }

    /** An event of this log's monitor, with its JSON. */
    public synchronized void event(LogEvent sent) {
        MonitorEvent e = sent.event();
        JsonNode node = sent.json();
        if (e instanceof MonitorEvent.ForecastChanged f) {
            // Forecasts change often: the tile shows the latest, and the last events keep room for the rest. A
            // deadline's forecast, and another bound property's, is its property's light's, from the monitor's
            // statuses.
            if (f.deadline() == null && (f.property() == null
                    || f.property().equals(safety.map(Bound::id).orElse(null)))) {
                setForecast(f.forecast(), node);
            }
            return;
        }
        lastEvents.addLast(node);
        if (lastEvents.size() > LAST_EVENTS) {
            lastEvents.removeFirst();
        }
        if (lights.event(e)) {
            return; // another property's warning or recovery: its own light and the last events
        }
        if (alarm.event(e, node)) {
            if (e instanceof MonitorEvent.Warning w && w.forecast() != null) {
                setForecast(w.forecast(), node);
            } else if (e instanceof MonitorEvent.Recovered) {
                forecast = null; // the forecast starts over
                forecastJson = null;
            }
        } else if (e instanceof MonitorEvent.Eliminated x) {
            eliminated.put(x.model(), "line " + x.line() + ": " + x.reason());
        } else if (e instanceof MonitorEvent.NoMatch n) {
            noMatch = true;
            noMatchLine = n.line();
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

    private void setForecast(Forecast f, JsonNode event) {
        forecast = f;
        forecastJson = TileJson.forecastOf(event);
    }

    /**
     * The models cannot judge this log ({@code why}, with the fix: not a monitor log, or an abstraction that does not
     * fit it): the tile shows no verdict and no forecast, whatever the monitor says.
     */
    public synchronized void noVerdict(String why) {
        noVerdict = why;
    }

    /** Every property after the latest record, as the monitor sees it. */
    public synchronized void properties(List<PropertyStatus> statuses) {
        lights.statuses(statuses);
    }

    private void startRun(int number, long first) {
        lights.reset();
        run = number;
        runLine = first;
        runRecords = 0;
        alarm.reset();
        noMatch = false;
        noMatchLine = 0;
        forecast = null;
        forecastJson = null;
        rest.reset();
        eliminated.clear();
        values.clear();
    }

    /**
     * A record of the log, after the monitor took it (so a new run has begun already if it begins one) and judged it
     * as {@code judged}: the headline property's value is the checker's reading of it, whatever its scope.
     */
    public synchronized void record(LogRecord r, PropertyView judged) {
        records++;
        runRecords++;
        line = r.line();
        clock = r.clock();
        rest.record(r);
        if (safety.isPresent()) {
            index = index < 0 ? judged.indexOf(safety.get().id()) : index;
            double v = index < 0 ? Double.NaN : judged.value(index);
            if (!Double.isNaN(v)) {
                values.add(r.time(), v);
            }
        }
    }

    /** The log grew (or was rotated) at this time. */
    public synchronized void grew(long nowMillis) {
        grewAtMillis = nowMillis;
    }

    /**
     * The state: no verdict where the models cannot judge the log; a violation while the property is violated; the
     * run ended once its log went quiet with the tree at rest; a warning while one is up; ok once the run recovered;
     * unknown where no model matches or the run does something no model does; ok once there is data (a reading of
     * the property; any record where there is no property); else waiting.
     *
     * @param quiet whether the log has not grown for the stale time
     */
    synchronized TileState state(boolean quiet) {
        boolean data = safety.isPresent() ? !values.isEmpty() : runRecords > 0;
        if (noVerdict != null) {
            return TileState.NO_VERDICT;
        }
        if (alarm.violatedNow()) {
            return TileState.VIOLATION;
        }
        if (quiet && runRecords > 0 && rest.atRest()) {
            return TileState.ENDED;
        }
        if (alarm.warnedNow()) {
            return TileState.WARNING;
        }
        if (alarm.recovered()) {
            return TileState.OK; // its alarm is over; the warning and the violation stay in the history
        }
        if (noMatch || (forecast != null && (forecast.novel() || forecast.basis() == Forecast.Basis.VALUE_ONLY))) {
            return TileState.UNKNOWN;
        }
        return data ? TileState.OK : TileState.WAITING;
    }

    /**
     * What the board knows of a tile beyond its log: the robot's name as shown (the part of the name all logs share
     * dropped), the property's recommended action, the probability at which the forecast warns (null when it does
     * not), whether the log's file exists, and whether the forecast has skill on these models (null when not
     * measured).
     */
    record Shown(String name, String action, Double warnsAt, boolean exists, Boolean skill,
                 Map<String, Boolean> skills) {
    }

    /** Whether the log has had no record since the start (so that whether its file exists is worth asking). */
    synchronized boolean empty() {
        return records == 0;
    }

    /** The tile as {@code /status} gives it; {@code stale} when the log has not grown for {@code staleMillis}. */
    public synchronized ObjectNode snapshot(long nowMillis, long staleMillis, Shown shown) {
        long quiet = Math.max(0, nowMillis - grewAtMillis);
        TileState state = state(quiet >= staleMillis);
        ObjectNode o = JSON.createObjectNode();
        o.put("log", log);
        o.put("name", shown.name());
        ArrayNode props = lights.json(state, noVerdict == null ? forecastJson : null, shown.skill(),
                shown.skills());
        // the robot's state is its worst property's; the forecast property's own stays beside it
        TileState robot = TileState.worst(state, props);
        o.put("state", robot.id());
        o.put("light", robot.light());
        o.put("forecastState", state.id());
        o.put("forecastLight", state.light());
        // Quiet mid-run is STALE (a logger or robot that stopped); quiet at rest is a run that ended, and a log that
        // never had a record is still waiting.
        o.put("stale", quiet >= staleMillis && state != TileState.ENDED && records > 0);
        o.put("quietSeconds", quiet / 1000.0);
        o.put("run", run);
        o.put("runLine", runLine);
        o.put("records", records);
        o.put("line", line);
        o.put("unit", clock.unit());
        o.put("property", safety.map(Bound::name).orElse(null));
        // the headline property's id, the key of its light in properties (its name may be shared or reworded)
        o.put("propertyId", safety.map(Bound::id).orElse(null));
        o.put("action", shown.action());
        o.put("exists", shown.exists());
        o.put("noVerdict", noVerdict);
        if (safety.isPresent()) {
            o.put("threshold", safety.get().floor());
        }
        number(o, "value", values.last());
        number(o, "battery", values.last()); // the older name of value, kept for existing readers of /status
        // Models that do not fit the log make no forecast worth showing.
        o.set("forecast", noVerdict == null ? forecastJson : null);
        if (shown.warnsAt() == null) {
            o.putNull("warnsAt");
        } else {
            o.put("warnsAt", shown.warnsAt());
        }
        alarm.snapshot(o);
        PropertyLights.outcome(o, props);
        o.set("properties", props);
        // the worst property's light, for the compact view and the order of the tiles
        o.set("worst", props.isEmpty() ? null : props.get(0));
        o.put("noMatch", noMatch);
        if (noMatch) {
            o.put("noMatchLine", noMatchLine);
        }
        o.put("treeAtRest", rest.known() ? rest.atRest() : null);
        ArrayNode running = o.putArray("running");
        rest.running().forEach(running::add);
        o.set("models", TileJson.models(models, eliminated));
        ArrayNode points = o.putArray("series");
        for (double[] p : values.points()) {
            points.addArray().add(p[0]).add(p[1]);
        }
        ArrayNode events = o.putArray("events");
        lastEvents.forEach(events::add);
        ArrayNode runs = o.putArray("earlierRuns");
        earlier.forEach(runs::add);
        o.put("earlierRunsOmitted", earlierOmitted);
        return o;
    }

    /** The run shown so far, as a line of the earlier runs. */
    private ObjectNode verdict() {
        ObjectNode o = JSON.createObjectNode();
        o.put("run", run);
        o.put("line", runLine);
        alarm.verdict(o);
        o.put("noMatch", noMatch);
        // A run that another followed is over: its light is what it came to, its worst property's.
        TileState own = state(false);
        ArrayNode props = lights.json(own, null, null, Map.of());
        TileState state = TileState.worst(own, props);
        o.put("state", state.id());
        o.put("light", state.light());
        PropertyLights.outcome(o, props);
        number(o, "probability", forecast == null ? Double.NaN : forecast.probability());
        return o;
    }
}
