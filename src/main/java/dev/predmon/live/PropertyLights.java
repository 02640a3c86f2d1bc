package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.event.ForecastJson;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.forecast.Survival;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PropertyStatus;
import dev.predmon.property.Property;
import dev.predmon.property.Verdict;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static dev.predmon.live.TileJson.JSON;
import static dev.predmon.live.TileJson.number;

/**
 * One light per property of a tile's run, worst first, as SCOPE's monitors show a robot's properties: red while the
 * property is violated, yellow while a warning of it is up, grey where nothing can be said (no reading yet, a run the
 * models cannot judge, an obligation pending longer than any training one, no evidence: nothing the property speaks of
 * occurred in the run), green while it holds, a pending obligation
 * included (it is the robot's ordinary work: its forecast says how it is going; a warning makes it yellow). Each light
 * has its property's verdict in words and its forecast where there is one, or says that there is none.
 *
 * <p>The verdicts and the deadline forecasts are the monitor's ({@link PropertyStatus}, handed over after each record);
 * the forecast's property follows the tile's own state (its violation ends when it holds again), and the warnings' and
 * recoveries' words come from the events. Bounded: one entry per property.
 */
final class PropertyLights {

    /** A light's state, worst first: the order on the page. */
    enum Light {
        VIOLATED("violated", "red"),
        WARNING("warning", "yellow"),
        UNKNOWN("unknown", "grey"),
        NO_EVIDENCE("no-evidence", "grey"),
        PENDING("pending", "green"),
        HOLDS("holds", "green");

        final String id;
        final String colour;

        Light(String id, String colour) {
            this.id = id;
            this.colour = colour;
        }

        /** The light whose {@code /status} state is {@code id}. */
        static Light of(String id) {
            for (Light l : values()) {
                if (l.id.equals(id)) {
                    return l;
                }
            }
            throw new IllegalArgumentException("no light '" + id + "'");
        }
    }

    private final List<Property> properties;
    private final String forecastId;
    private List<PropertyStatus> now = List.of();
    /** Each property's warning reason while it is up, and its last recovery's, by id. */
    private final Map<String, String> warnings = new HashMap<>();
    private final Map<String, String> recoveries = new HashMap<>();

    /**
     * @param properties every property of the abstraction, in its order
     * @param forecastId the id of the forecast's property, or null
     */
    PropertyLights(List<Property> properties, String forecastId) {
        this.properties = List.copyOf(properties);
        this.forecastId = forecastId;
    }

    /** The monitor's view of every property after the latest record. */
    void statuses(List<PropertyStatus> statuses) {
        now = statuses;
    }

    /**
     * An event of another property than the forecast's (a deadline's or another bound's warning, a recovery): whether
     * it is one of the lights'.
     */
    boolean event(MonitorEvent e) {
        if (e instanceof MonitorEvent.Warning w && w.property() != null && !w.property().equals(forecastId)) {
            warnings.put(w.property(), w.reason());
            recoveries.remove(w.property());
            return true;
        }
        if (e instanceof MonitorEvent.Recovered r && r.property() != null && !r.property().equals(forecastId)) {
            warnings.remove(r.property());
            recoveries.put(r.property(), r.reason());
            return true;
        }
        return false;
    }

    /** A new run. */
    void reset() {
        now = List.of();
        warnings.clear();
        recoveries.clear();
    }

    /**
     * Every property's light, worst first, each as {@code /status} gives it.
     *
     * @param state    the tile's state: the forecast property's light
     * @param forecast the forecast property's latest forecast as JSON, or null
     * @param skill    whether the forecast has skill on these models (null when it was not measured)
     * @param skills   whether each property's forecast has skill, by the property's name, as its scorecard says
     */
    ArrayNode json(TileState state, JsonNode forecast, Boolean skill, Map<String, Boolean> skills) {
        List<ObjectNode> lights = new ArrayList<>();
        Map<String, PropertyStatus> byId = new HashMap<>();
        for (PropertyStatus s : now) {
            byId.put(s.property().id(), s);
        }
        for (Property p : properties) {
            PropertyStatus s = byId.get(p.id());
            if (state == TileState.NO_VERDICT && !p.id().equals(forecastId)) {
                s = null; // models that do not fit the log: what its checks say of it is no verdict either
            }
            lights.add(p.id().equals(forecastId) ? forecastLight(p, s, state, forecast, skill) : light(p, s,
                    state == TileState.NO_VERDICT, skills.get(p.name())));
        }
        // stable: the abstraction's order within a light
        lights.sort(Comparator.comparing(o -> Light.of(o.get("state").asText())));
        ArrayNode a = JSON.createArrayNode();
        lights.forEach(a::add);
        return a;
    }

    /**
     * The run's outcome beside its lights, in {@code o}: {@code violated} and {@code warned}, the ids of the
     * properties whose light is red and yellow, worst first.
     */
    static void outcome(ObjectNode o, ArrayNode lights) {
        ArrayNode violated = o.putArray("violated");
        ArrayNode warned = o.putArray("warned");
        for (JsonNode p : lights) {
            String state = p.path("state").asText();
            if (state.equals(Light.VIOLATED.id)) {
                violated.add(p.path("property").asText());
            } else if (state.equals(Light.WARNING.id)) {
                warned.add(p.path("property").asText());
            }
        }
    }

    private ObjectNode base(Property p, Verdict v, Light light) {
        ObjectNode o = JSON.createObjectNode();
        o.put("property", p.id());
        o.put("name", p.name());
        o.put("kind", p.kind());
        o.put("state", light.id);
        o.put("light", light.colour);
        o.put("verdict", v == null ? null : v.id());
        if (v instanceof Verdict.Violated x) {
            o.put("line", x.line());
            o.put("time", x.time());
            if (x.value() != null) {
                o.put("value", x.value());
            }
            o.put("what", x.what());
        } else if (v instanceof Verdict.Pending x) {
            o.put("line", x.line());
            o.put("since", x.since());
            o.put("deadline", x.deadline());
            o.put("unit", x.unit().key);
        } else if (v instanceof Verdict.NoEvidence x) {
            o.put("what", x.why());
        }
        o.put("action", p.action());
        return o;
    }

    /** A property other than the forecast's. */
    private ObjectNode light(Property p, PropertyStatus s, boolean noVerdict, Boolean skill) {
        Verdict v = s == null ? null : s.verdict();
        Survival.Estimate e = s == null ? null : s.deadline();
        Light light;
        String words;
        if (v == null) {
            light = Light.UNKNOWN;
            words = noVerdict ? "no verdict: the models cannot judge this log" : "no record of the run yet";
        } else if (v instanceof Verdict.Violated) {
            light = Light.VIOLATED;
            words = v.describe();
        } else if (s.warned()) {
            light = Light.WARNING;
            words = warnings.getOrDefault(p.id(), "warned: " + v.describe());
        } else if (v instanceof Verdict.NoEvidence) {
            light = Light.NO_EVIDENCE;
            words = v.describe();
        } else if (v instanceof Verdict.Pending && e != null && e.novel()) {
            light = Light.UNKNOWN;
            words = "no evidence: " + v.describe() + ", longer than any training obligation";
        } else {
            light = v instanceof Verdict.Pending ? Light.PENDING : Light.HOLDS;
            words = v.describe();
        }
        ObjectNode o = base(p, v, light);
        o.put("words", words);
        o.put("model", s == null ? PropertyStatus.Model.NONE.id() : s.model().id());
        if (s != null && s.model() == PropertyStatus.Model.FORECAST) {
            return valueForecast(o, s, skill, light);
        }
        if (e != null) {
            ObjectNode f = o.putObject("forecast");
            number(f, "probability", e.novel() ? Double.NaN : e.probability());
            f.put("timeLeft", e.timeLeft());
            f.put("unit", s.unit());
            f.put("novel", e.novel());
            f.put("atRisk", e.atRisk());
            f.put("longer", e.longer());
        } else {
            o.putNull("forecast");
        }
        // a deadline forecast's skill, as its scorecard says: where none measured it, the page says so beside it
        if (skill == null || e == null) {
            o.putNull("skill");
        } else {
            o.put("skill", skill);
        }
        o.put("forecastWords", forecastWords(s, e, skill));
        String recovery = recoveries.get(p.id());
        o.put("recovery", light == Light.WARNING ? null : recovery);
        return o;
    }

    private static String forecastWords(PropertyStatus s, Survival.Estimate e, Boolean skill) {
        if (s == null || s.model() == PropertyStatus.Model.NONE) {
            return s == null ? "no forecast: no model of this property" : s.noForecastWords();
        }
        if (e == null) {
            return "no forecast: no obligation pending";
        }
        String left = ForecastWords.fixed(e.timeLeft(), 0) + " " + s.unit() + " left";
        if (e.novel()) {
            return "no forecast: pending longer than any training obligation; " + left;
        }
        if (Boolean.FALSE.equals(skill)) {
            // no headline: the number would look like knowledge the models showed they lack
            return "no skill: the deadline forecast did no better than the base rate; " + left;
        }
        return "P(miss) " + Math.round(e.probability() * 100) + "%, " + left + (skill == null ? " (skill not measured)"
                : "");
    }

    /** A bound property with a value forecast of its own: its latest forecast, as the forecast's property's. */
    private ObjectNode valueForecast(ObjectNode o, PropertyStatus s, Boolean skill, Light light) {
        Forecast f = s.forecast();
        if (f == null) {
            o.putNull("forecast");
        } else {
            o.set("forecast", JSON.valueToTree(ForecastJson.of(f)));
        }
        if (skill == null) {
            o.putNull("skill");
        } else {
            o.put("skill", skill);
        }
        o.put("forecastWords", f == null ? "no forecast yet"
                : f.basis() == Forecast.Basis.VIOLATED ? "no forecast: the property is violated"
                : Boolean.FALSE.equals(skill) ? "no skill: the forecast did no better than the base rate"
                : "P(violation) " + Math.round(f.probability() * 100) + "%, "
                // not warned: no countdown to a violation its rule does not expect
                + (light == Light.WARNING ? ForecastWords.time(f) : "no warning")
                + (skill == null ? " (skill not measured)" : ""));
        String recovery = recoveries.get(s.property().id());
        o.put("recovery", light == Light.WARNING ? null : recovery);
        return o;
    }

    /** The forecast's property: its light is the tile's. */
    private ObjectNode forecastLight(Property p, PropertyStatus s, TileState state, JsonNode forecast, Boolean skill) {
        Verdict v = s == null ? null : s.verdict();
        Light light = switch (state) {
            case VIOLATION -> Light.VIOLATED;
            case WARNING -> Light.WARNING;
            case UNKNOWN, NO_VERDICT, WAITING -> Light.UNKNOWN;
            case ENDED -> v instanceof Verdict.Violated ? Light.VIOLATED : v instanceof Verdict.NoEvidence
                    ? Light.NO_EVIDENCE : Light.HOLDS;
            case OK -> v instanceof Verdict.NoEvidence ? Light.NO_EVIDENCE : Light.HOLDS;
        };
        ObjectNode o = base(p, v, light);
        o.put("words", switch (state) {
            case VIOLATION -> v == null ? "violated" : v.describe();
            case WARNING -> "a violation is predicted";
            case UNKNOWN -> "unknown: the models cannot tell what this run does";
            case NO_VERDICT -> "no verdict: the models cannot judge this log";
            case WAITING -> "no reading yet";
            case ENDED -> "run ended: " + (v == null ? "holds" : v.describe());
            case OK -> v instanceof Verdict.Violated ? "holds again" : v instanceof Verdict.NoEvidence ? v.describe()
                    : "holds";
        });
        o.put("model", PropertyStatus.Model.FORECAST.id());
        o.set("forecast", forecast == null ? null : forecast.deepCopy());
        if (skill == null) {
            o.putNull("skill");
        } else {
            o.put("skill", skill);
        }
        o.put("forecastWords", forecast == null ? "no forecast yet"
                : Boolean.FALSE.equals(skill) ? "no skill: the forecast did no better than the base rate"
                : "P(violation) " + Math.round(forecast.path("probability").asDouble() * 100) + "%");
        o.putNull("recovery");
        return o;
    }
}
