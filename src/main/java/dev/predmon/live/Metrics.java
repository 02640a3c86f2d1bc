package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.monitor.MonitorEvent;
import io.prometheus.metrics.core.metrics.Counter;
import io.prometheus.metrics.core.metrics.GaugeWithCallback;
import io.prometheus.metrics.expositionformats.PrometheusTextFormatWriter;
import io.prometheus.metrics.model.registry.PrometheusRegistry;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;

/**
 * {@code /metrics}: what the live view shows, for Prometheus, in its text format, through the official Prometheus
 * Java client. Per log and per property (labels {@code log}, {@code robot}, {@code property}; {@code robot} is the
 * robot's whole name, the same on every series and at every scrape):
 * <ul>
 *   <li>{@code predmon_state{state=...}}: 1 for the robot's state, its worst property's, 0 for each other one (a state
 *       set);</li>
 *   <li>{@code predmon_stale}: 1 while the log is STALE;</li>
 *   <li>{@code predmon_violation_probability}: the latest forecast's probability (0 to 1);</li>
 *   <li>{@code predmon_time_to_violation_seconds}, or {@code predmon_time_to_violation_ticks} for a log counted in
 *       ticks: the latest forecast's time left, while a violation is in sight;</li>
 *   <li>{@code predmon_value}: the last reading of the property's value;</li>
 *   <li>{@code predmon_warnings_total}, {@code predmon_violations_total}: counted since watch started, over every
 *       run and rotation of the log.</li>
 * </ul>
 * And per property of the abstraction, each labelled with its id ({@code property="no-abort"}):
 * <ul>
 *   <li>{@code predmon_property_state{state=...}}: 1 for its light's state (holds, pending, warning, unknown,
 *       violated), 0 for each other one;</li>
 *   <li>{@code predmon_property_probability}: its latest forecast's probability of a violation (of a miss, for a
 *       deadline), absent without one;</li>
 *   <li>{@code predmon_property_time_left{unit=...}}: a pending deadline's time left, in its unit (ticks, seconds,
 *       occurrences);</li>
 *   <li>{@code predmon_property_warnings_total}, {@code predmon_property_violations_total}: its warnings and
 *       violations since watch started.</li>
 * </ul>
 * The gauges are read from the tiles at each scrape, as {@code /status} gives them, so that {@code /metrics} never
 * says other than the page; the counters count the events as they come. A gauge with nothing to say (no forecast
 * yet, no reading) is left out rather than given a made-up value.
 */
final class Metrics {

    /** What {@link #scrape()} answers: the Prometheus text format, version 0.0.4. */
    static final String CONTENT_TYPE = PrometheusTextFormatWriter.CONTENT_TYPE;

    private static final PrometheusTextFormatWriter WRITER = PrometheusTextFormatWriter.create();
    private static final String[] LABELS = {"log", "robot", "property"};

    private final PrometheusRegistry registry = new PrometheusRegistry();
    private final Supplier<ObjectNode> status;
    private final String property;
    private final String forecastId;
    private final Counter warnings;
    private final Counter violations;
    private final Counter propertyWarnings;
    private final Counter propertyViolations;
    /** Per log, the property labels its counters got from events beyond {@link #properties}. */
    private final Map<String, Set<String>> counted = new HashMap<>();
    /** The robot's whole name of a log, the {@code robot} label. */
    private final Function<String, String> robots;
    /** The ids of the abstraction's properties, whose counters start at 0 with each tile. */
    private final List<String> properties;
    /** The tiles of the scrape under way, as {@code /status} gives them; read by the gauges' callbacks. */
    private List<JsonNode> tiles = List.of();

    /**
     * @param status   the board's {@code /status} of every log
     * @param property the property's name, the {@code property} label ("" where the abstraction has none)
     */
    Metrics(Supplier<ObjectNode> status, String property) {
        this(status, property, List.of());
    }

    /** As above, with the ids of every property of the abstraction. */
    Metrics(Supplier<ObjectNode> status, String property, List<String> properties) {
        this(status, property, properties, null, RobotNames.byFile()::of);
    }

    /**
     * As above, {@code forecastId} the id of the property of the {@code property} label (null when not known): another
     * bound property's warnings are its own, not that property's; {@code robots} gives each log its label
     * of the robot.
     */
    Metrics(Supplier<ObjectNode> status, String property, List<String> properties, String forecastId,
            Function<String, String> robots) {
        this.forecastId = forecastId;
        this.robots = robots;
        this.status = status;
        this.property = property;
        this.properties = List.copyOf(properties);
        List<String> states = new ArrayList<>();
        for (TileState s : TileState.values()) {
            states.add(s.id());
        }
        gauge("predmon_state", "The log's state as the live view shows it: 1 for the current one, 0 for the others "
                + "(" + String.join(", ", states) + ")", cb -> forEachTile(t -> {
                    Set<String> all = new LinkedHashSet<>(states);
                    String now = t.get("state").asText();
                    all.add(now);
                    for (String s : all) {
                        cb.call(s.equals(now) ? 1 : 0, labels(t, s));
                    }
                }), "state");
        gauge("predmon_stale", "1 while the log has not grown for the stale time in the middle of a run", cb ->
                forEachTile(t -> cb.call(t.get("stale").asBoolean() ? 1 : 0, labels(t))));
        gauge("predmon_violation_probability", "The latest forecast's probability that the run violates the property "
                + "(0 to 1)", cb -> forEachTile(t -> {
                    JsonNode f = t.get("forecast");
                    if (number(f, "probability")) {
                        cb.call(f.get("probability").asDouble(), labels(t));
                    }
                }));
        for (String unit : List.of("seconds", "ticks")) {
            gauge("predmon_time_to_violation_" + unit, "The latest forecast's expected time to the violation, in "
                    + unit + (unit.equals("ticks") ? " of the behaviour tree (logs without time stamps)" : "")
                    + "; absent while no violation is in sight", cb -> forEachTile(t -> {
                        JsonNode f = t.get("forecast");
                        String u = f != null && f.hasNonNull("unit") ? f.get("unit").asText() : t.get("unit").asText();
                        if (number(f, "timeToViolation") && (u.equals("s") ? "seconds" : u).equals(unit)) {
                            cb.call(f.get("timeToViolation").asDouble(), labels(t));
                        }
                    }));
        }
        gauge("predmon_value", "The last reading of the property's value", cb -> forEachTile(t -> {
                    if (number(t, "value")) {
                        cb.call(t.get("value").asDouble(), labels(t));
                    }
                }));
        List<String> lights = new ArrayList<>();
        for (PropertyLights.Light l : PropertyLights.Light.values()) {
            lights.add(l.id);
        }
        propertyGauge("predmon_property_state", "Each property's light: 1 for its state, 0 for the others ("
                + String.join(", ", lights) + ")", (cb, t, p) -> {
                    String now = p.get("state").asText();
                    for (String l : lights) {
                        cb.call(l.equals(now) ? 1 : 0, t.get("log").asText(), robot(t),
                                p.get("property").asText(), l);
                    }
                }, "state");
        propertyGauge("predmon_property_probability", "Each property's latest forecast: the probability of a violation"
                + " (of a missed deadline for a bounded response), 0 to 1", (cb, t, p) -> {
                    if (number(p.get("forecast"), "probability")) {
                        cb.call(p.get("forecast").get("probability").asDouble(), t.get("log").asText(),
                                robot(t), p.get("property").asText());
                    }
                });
        propertyGauge("predmon_property_time_left", "A pending bounded response's time left before its deadline, in "
                + "the unit of the label", (cb, t, p) -> {
                    if (number(p.get("forecast"), "timeLeft")) {
                        cb.call(p.get("forecast").get("timeLeft").asDouble(), t.get("log").asText(),
                                robot(t), p.get("property").asText(),
                                p.get("forecast").get("unit").asText());
                    }
                }, "unit");
        propertyWarnings = (Counter) Counter.builder().name("predmon_property_warnings_total").labelNames(LABELS)
                .help("Each property's warnings since watch started, over every run of the log").withoutExemplars()
                .register(registry);
        propertyViolations = (Counter) Counter.builder().name("predmon_property_violations_total").labelNames(LABELS)
                .help("Each property's violations since watch started, over every run of the log").withoutExemplars()
                .register(registry);
        warnings = (Counter) Counter.builder().name("predmon_warnings_total").labelNames(LABELS)
                .help("Warnings raised since watch started, over every run of the log").withoutExemplars()
                .register(registry);
        violations = (Counter) Counter.builder().name("predmon_violations_total").labelNames(LABELS)
                .help("Violations of the property since watch started, over every run of the log").withoutExemplars()
                .register(registry);
    }

    private void gauge(String name, String help, Consumer<GaugeWithCallback.Callback> callback, String... more) {
        String[] labels = new String[LABELS.length + more.length];
        System.arraycopy(LABELS, 0, labels, 0, LABELS.length);
        System.arraycopy(more, 0, labels, LABELS.length, more.length);
        GaugeWithCallback.builder().name(name).help(help).labelNames(labels).callback(callback).register(registry);
    }

    /** What a per-property gauge says of one property of one tile. */
    @FunctionalInterface
    private interface PropertyReading {
        void read(GaugeWithCallback.Callback cb, JsonNode tile, JsonNode property);
    }

    private void propertyGauge(String name, String help, PropertyReading reading, String... more) {
        gauge(name, help, cb -> forEachTile(t -> t.path("properties").forEach(p -> reading.read(cb, t, p))), more);
    }

    private void forEachTile(Consumer<JsonNode> each) {
        tiles.forEach(each);
    }

    private String[] labels(JsonNode tile, String... more) {
        String[] values = new String[LABELS.length + more.length];
        values[0] = tile.get("log").asText();
        values[1] = robot(tile);
        values[2] = property;
        System.arraycopy(more, 0, values, LABELS.length, more.length);
        return values;
    }

    /**
     * The {@code robot} label of a tile: its robot's whole name, as {@link Tile#name} has it from the first scrape on,
     * the same on every series. Not the page's short name, which drops what all the logs' names share and so changes
     * when a log appears.
     */
    private String robot(JsonNode tile) {
        return robots.apply(tile.get("log").asText());
    }

    private static boolean number(JsonNode o, String field) {
        return o != null && o.hasNonNull(field) && o.get(field).isNumber() && Double.isFinite(o.get(field).asDouble());
    }

    /** A tile was made: its counters start at 0, so that an alert on their increase sees the first warning. */
    void added(Tile tile) {
        warnings.initLabelValues(tile.log(), tile.name(), property);
        violations.initLabelValues(tile.log(), tile.name(), property);
        for (String p : properties) {
            propertyWarnings.initLabelValues(tile.log(), tile.name(), p);
            propertyViolations.initLabelValues(tile.log(), tile.name(), p);
        }
    }

    /** A tile left the board (its log was deleted long ago): its counters' series go with it. */
    synchronized void removed(Tile tile) {
        warnings.remove(tile.log(), tile.name(), property);
        violations.remove(tile.log(), tile.name(), property);
        Set<String> all = new LinkedHashSet<>(properties);
        all.addAll(counted.getOrDefault(tile.log(), Set.of()));
        counted.remove(tile.log());
        for (String p : all) {
            propertyWarnings.remove(tile.log(), tile.name(), p);
            propertyViolations.remove(tile.log(), tile.name(), p);
        }
    }

    /** A per-property counter of {@code tile} has a series for {@code id} (one not listed in advance too). */
    private synchronized void counted(Tile tile, String id) {
        if (!properties.contains(id)) {
            counted.computeIfAbsent(tile.log(), l -> new LinkedHashSet<>()).add(id);
        }
    }

    /** An event of {@code tile}'s log. */
    void event(Tile tile, MonitorEvent e) {
        if (e instanceof MonitorEvent.Warning w && w.property() != null) {
            counted(tile, w.property());
            propertyWarnings.labelValues(tile.log(), tile.name(), w.property()).inc();
        } else if (e instanceof MonitorEvent.Violation v && v.property() != null) {
            counted(tile, v.property());
            propertyViolations.labelValues(tile.log(), tile.name(), v.property()).inc();
        }
        if (e instanceof MonitorEvent.Warning w && w.clause() != MonitorEvent.Clause.DEADLINE
                && (forecastId == null || w.property() == null || w.property().equals(forecastId))) {
            // this label is the forecast's property; a deadline's warnings are its own property's
            warnings.labelValues(tile.log(), tile.name(), property).inc();
        } else if (e instanceof MonitorEvent.Violation v && v.forecast()) {
            // this label is the forecast's property; the other properties' violations are not its own
            violations.labelValues(tile.log(), tile.name(), property).inc();
        }
    }

    /** The text {@code /metrics} answers now. */
    synchronized byte[] scrape() {
        List<JsonNode> now = new ArrayList<>();
        status.get().get("logs").forEach(now::add);
        tiles = now;
        try {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            WRITER.write(out, registry.scrape());
            return out.toByteArray();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot happen: writing to memory", e);
        } finally {
            tiles = List.of();
        }
    }
}
