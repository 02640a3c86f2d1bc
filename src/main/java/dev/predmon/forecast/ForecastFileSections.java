package dev.predmon.forecast;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.Iterator;
import java.util.Map;
import java.util.TreeMap;

/**
 * The parts of {@code forecast.json} beside the per-state tables ({@link ForecastFile}): the calibration, the
 * scorecards, and per bounded-response property its training obligations with the rule its deadline forecast warns
 * by; and the number reading and writing the whole file shares. Every part added after the first format is optional,
 * so that an older file still reads.
 */
final class ForecastFileSections {

    private ForecastFileSections() {
    }

    /** {@code c} under {@code calibration}, when it was fitted (the identity is written as nothing). */
    static void writeCalibration(ObjectNode n, Calibration c) {
        if (c.runs() > 0) {
            ObjectNode o = n.putObject("calibration");
            o.put("slope", c.slope());
            o.put("intercept", c.intercept());
            o.put("runs", c.runs());
        }
    }

    /** The calibration object {@code c}; {@code at} says where it is, for the message. */
    static Calibration calibration(JsonNode c, String at) {
        if (!c.isObject()) {
            throw new IllegalArgumentException("'" + at + "': expected an object");
        }
        double slope = number(c, "slope");
        if (!(slope > 0)) {
            throw new IllegalArgumentException("'" + at + "/slope': expected a positive number");
        }
        double intercept = number(c, "intercept");
        if (Double.isNaN(intercept)) {
            throw new IllegalArgumentException("'" + at + "/intercept': expected a number");
        }
        return new Calibration(slope, intercept, count(c, "runs", at));
    }

    /**
     * The optional {@code obligations}: per bounded-response property, the training obligations' durations and,
     * when one was learned, the rule its deadline forecast warns by.
     */
    static void writeObligations(ObjectNode root, Map<String, Survival> obligations, Map<String, DeadlineRule> rules) {
        if (obligations.isEmpty()) {
            return;
        }
        ObjectNode o = root.putObject("obligations");
        new TreeMap<>(obligations).forEach((id, survival) -> {
            ObjectNode n = o.putObject(id);
            numbers(n.putArray("discharged"), survival.discharged());
            numbers(n.putArray("censored"), survival.censored());
            if (!survival.contexts().isEmpty()) {
                ObjectNode by = n.putObject("byInput");
                survival.contexts().forEach((input, s) -> {
                    ObjectNode c = by.putObject(input);
                    numbers(c.putArray("discharged"), s.discharged());
                    numbers(c.putArray("censored"), s.censored());
                });
            }
            DeadlineRule rule = rules.get(id);
            if (rule != null) {
                n.put("threshold", rule.threshold());
                n.put("note", rule.note());
                n.put("validated", rule.validated());
                writeCalibration(n, rule.calibration());
                if (rule.margin() != DeadlineRule.HALF) {
                    n.put("margin", rule.margin());
                }
                if (rule.late()) {
                    n.put("level", rule.level());
                    if (rule.waited()) {
                        n.put("lateCeiling", "every");
                    }
                }
                if (rule.baseline()) {
                    n.put("rule", "baseline");
                }
            }
        });
    }

    /** The training obligations of {@link #writeObligations}. */
    static Map<String, Survival> readObligations(JsonNode root) {
        Map<String, Survival> obligations = new TreeMap<>();
        for (Map.Entry<String, JsonNode> e : obligationNodes(root).entrySet()) {
            try {
                Survival pooled = new Survival(doubles(required(e.getValue(), "discharged")),
                        doubles(required(e.getValue(), "censored")));
                JsonNode by = e.getValue().get("byInput");
                if (by != null) {
                    if (!by.isObject()) {
                        throw new IllegalArgumentException("'byInput': expected an object");
                    }
                    Map<String, Survival> contexts = new TreeMap<>();
                    for (Iterator<Map.Entry<String, JsonNode>> it = by.fields(); it.hasNext(); ) {
                        Map.Entry<String, JsonNode> c = it.next();
                        contexts.put(c.getKey(), new Survival(doubles(required(c.getValue(), "discharged")),
                                doubles(required(c.getValue(), "censored"))));
                    }
                    pooled = pooled.withContexts(contexts);
                }
                obligations.put(e.getKey(), pooled);
            } catch (IllegalArgumentException x) {
                throw new IllegalArgumentException("'obligations/" + e.getKey() + "': " + x.getMessage(), x);
            }
        }
        return obligations;
    }

    /** The deadline rules of {@link #writeObligations}: a property without a {@code threshold} has none. */
    static Map<String, DeadlineRule> readDeadlines(JsonNode root) {
        Map<String, DeadlineRule> rules = new TreeMap<>();
        for (Map.Entry<String, JsonNode> e : obligationNodes(root).entrySet()) {
            JsonNode n = e.getValue();
            if (n.get("threshold") == null) {
                continue;
            }
            String at = "obligations/" + e.getKey();
            double threshold = number(n, "threshold");
            if (!((threshold >= 0 && threshold <= 1) || threshold == DeadlineRule.NEVER)) {
                throw new IllegalArgumentException("'" + at + "/threshold': " + n.get("threshold")
                        + " is not a probability (from 0 to 1), nor " + (int) DeadlineRule.NEVER
                        + " (the probability does not warn)");
            }
            JsonNode validated = required(n, "validated");
            if (!validated.isBoolean()) {
                throw new IllegalArgumentException("'" + at + "/validated': expected true or false");
            }
            JsonNode c = n.get("calibration");
            double margin = n.has("margin") ? number(n, "margin") : DeadlineRule.HALF;
            if (!(margin >= 0 && margin <= 1)) {
                throw new IllegalArgumentException("'" + at + "/margin': " + n.get("margin")
                        + " is not a share (from 0 to 1)");
            }
            double level = n.has("level") ? number(n, "level") : Double.NaN;
            if (n.has("level") && !(level > 0.5 && level < 1)) {
                throw new IllegalArgumentException("'" + at + "/level': " + n.get("level")
                        + " is not a prediction level (above 0.5 and below 1)");
            }
            JsonNode ceiling = n.get("lateCeiling");
            if (ceiling != null && !(ceiling.isTextual() && ceiling.asText().equals("every"))) {
                throw new IllegalArgumentException("'" + at + "/lateCeiling': expected \"every\"");
            }
            JsonNode rule = n.get("rule");
            if (rule != null && !(rule.isTextual() && rule.asText().equals("baseline"))) {
                throw new IllegalArgumentException("'" + at + "/rule': expected \"baseline\"");
            }
            rules.put(e.getKey(), new DeadlineRule(threshold, required(n, "note").asText(), validated.booleanValue(),
                    c == null ? Calibration.IDENTITY : calibration(c, at + "/calibration"), margin, rule != null,
                    level, ceiling != null));
        }
        return rules;
    }

    private static Map<String, JsonNode> obligationNodes(JsonNode root) {
        Map<String, JsonNode> nodes = new TreeMap<>();
        JsonNode o = root.get("obligations");
        if (o == null) {
            return nodes;
        }
        if (!o.isObject()) {
            throw new IllegalArgumentException("'obligations': expected an object");
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = o.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            if (!e.getValue().isObject()) {
                throw new IllegalArgumentException("'obligations/" + e.getKey() + "': expected an object");
            }
            nodes.put(e.getKey(), e.getValue());
        }
        return nodes;
    }

    /**
     * Which clauses warn ({@link Clauses}), written only when not every clause of the forecast's rule does, so that a
     * file learned before the choice reads as it did: {@code "rule": "baseline"} for the raw-value baseline,
     * {@code "matching": false} for the forecast's rule without the thesis's matching.
     */
    static void writeClauses(ObjectNode root, Clauses c) {
        if (c.baseline()) {
            root.put("rule", "baseline");
        } else if (!c.matching()) {
            root.put("matching", false);
        }
    }

    /** The clauses of {@link #writeClauses}: every clause when neither key is there. */
    static Clauses readClauses(JsonNode root) {
        JsonNode rule = root.get("rule");
        if (rule != null && !(rule.isTextual() && (rule.asText().equals("baseline")
                || rule.asText().equals("forecast")))) {
            throw new IllegalArgumentException("'rule': expected \"baseline\" or \"forecast\"");
        }
        JsonNode matching = root.get("matching");
        if (matching != null && !matching.isBoolean()) {
            throw new IllegalArgumentException("'matching': expected true or false");
        }
        if (rule != null && rule.asText().equals("baseline")) {
            return Clauses.BASELINE;
        }
        return matching == null || matching.booleanValue() ? Clauses.ALL : Clauses.NO_MATCHING;
    }

    static void number(ObjectNode n, String key, double v) {
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            n.putNull(key);
        } else {
            n.put(key, v);
        }
    }

    static void numbers(ArrayNode a, double[] values) {
        for (double v : values) {
            if (Double.isNaN(v) || Double.isInfinite(v)) {
                a.addNull();
            } else {
                a.add(v);
            }
        }
    }

    static JsonNode required(JsonNode n, String key) {
        JsonNode v = n.get(key);
        if (v == null) {
            throw new IllegalArgumentException("'" + key + "' is missing");
        }
        return v;
    }

    static int integer(JsonNode n, String key) {
        JsonNode v = required(n, key);
        if (!v.canConvertToInt() || !v.isIntegralNumber()) {
            throw new IllegalArgumentException("'" + key + "': expected a whole number");
        }
        return v.intValue();
    }

    /** A count: a whole number, 0 or more; {@code at} says where, null at the top. */
    static int count(JsonNode n, String key, String at) {
        int v = integer(n, key);
        if (v < 0) {
            throw new IllegalArgumentException("'" + (at == null ? "" : at + "/") + key + "': " + v
                    + ", expected 0 or more");
        }
        return v;
    }

    static double number(JsonNode n, String key) {
        JsonNode v = required(n, key);
        if (v.isNull()) {
            return Double.NaN;
        }
        if (!v.isNumber()) {
            throw new IllegalArgumentException("'" + key + "': expected a number or null");
        }
        return v.doubleValue();
    }

    static double[] doubles(JsonNode a) {
        if (!a.isArray()) {
            throw new IllegalArgumentException("expected an array of numbers");
        }
        double[] out = new double[a.size()];
        for (int i = 0; i < out.length; i++) {
            JsonNode v = a.get(i);
            if (!v.isNull() && !v.isNumber()) {
                throw new IllegalArgumentException("expected an array of numbers");
            }
            out[i] = v.isNull() ? Double.NaN : v.doubleValue();
        }
        return out;
    }
}
