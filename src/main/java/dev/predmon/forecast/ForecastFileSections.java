package dev.predmon.forecast;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
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
            DeadlineRule rule = rules.get(id);
            if (rule != null) {
                n.put("threshold", rule.threshold());
                n.put("note", rule.note());
                n.put("validated", rule.validated());
                writeCalibration(n, rule.calibration());
            }
        });
    }

    /** The training obligations of {@link #writeObligations}. */
    static Map<String, Survival> readObligations(JsonNode root) {
        Map<String, Survival> obligations = new TreeMap<>();
        for (Map.Entry<String, JsonNode> e : obligationNodes(root).entrySet()) {
            try {
                obligations.put(e.getKey(), new Survival(doubles(required(e.getValue(), "discharged")),
                        doubles(required(e.getValue(), "censored"))));
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
            if (!(threshold >= 0 && threshold <= 1)) {
                throw new IllegalArgumentException("'" + at + "/threshold': " + n.get("threshold")
                        + " is not a probability (from 0 to 1)");
            }
            JsonNode validated = required(n, "validated");
            if (!validated.isBoolean()) {
                throw new IllegalArgumentException("'" + at + "/validated': expected true or false");
            }
            JsonNode c = n.get("calibration");
            rules.put(e.getKey(), new DeadlineRule(threshold, required(n, "note").asText(), validated.booleanValue(),
                    c == null ? Calibration.IDENTITY : calibration(c, at + "/calibration")));
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

    /** The optional {@code scorecards} list: one object per property, written only when there is one. */
    static void writeScorecards(ObjectNode root, List<Scorecard> cards) {
        if (cards.isEmpty()) {
            return;
        }
        ArrayNode a = root.putArray("scorecards");
        cards.forEach(c -> a.add(scorecard(c)));
    }

    /** One scorecard as {@code forecast.json} holds it (and {@code /status} shows it). */
    static ObjectNode scorecard(Scorecard c) {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("property", c.property());
        n.put("folds", c.folds());
        n.put("runs", c.runs());
        n.put("violating", c.violating());
        n.put("warned", c.warned());
        n.put("falseAlarms", c.falseAlarms());
        number(n, "medianLead", c.medianLead());
        n.put("unit", c.unit());
        number(n, "brier", c.brier());
        number(n, "baseBrier", c.baseBrier());
        if (!Scorecard.RUNS.equals(c.counted())) {
            n.put("counted", c.counted());
        }
        return n;
    }

    static List<Scorecard> readScorecards(JsonNode root) {
        JsonNode a = root.get("scorecards");
        if (a == null) {
            return List.of();
        }
        if (!a.isArray()) {
            throw new IllegalArgumentException("'scorecards': expected an array");
        }
        List<Scorecard> cards = new ArrayList<>();
        for (JsonNode n : a) {
            if (!n.isObject()) {
                throw new IllegalArgumentException("'scorecards': expected an array of objects");
            }
            Scorecard c = new Scorecard(required(n, "property").asText(), integer(n, "folds"), integer(n, "runs"),
                    integer(n, "violating"), integer(n, "warned"), integer(n, "falseAlarms"), number(n, "medianLead"),
                    required(n, "unit").asText(), number(n, "brier"), number(n, "baseBrier"),
                    n.has("counted") ? n.get("counted").asText() : Scorecard.RUNS);
            if (c.runs() < 0 || c.violating() < 0 || c.violating() > c.runs() || c.warned() < 0
                    || c.warned() > c.violating() || c.falseAlarms() < 0 || c.falseAlarms() > c.held()) {
                throw new IllegalArgumentException("'scorecards' of '" + c.property() + "': expected 0 <= warned <= "
                        + "violating <= runs and 0 <= falseAlarms <= runs - violating");
            }
            if (!(Double.isNaN(c.brier()) || (c.brier() >= 0 && c.brier() <= 1))
                    || !(Double.isNaN(c.baseBrier()) || (c.baseBrier() >= 0 && c.baseBrier() <= 1))) {
                throw new IllegalArgumentException("'scorecards' of '" + c.property() + "': expected Brier scores "
                        + "between 0 and 1");
            }
            cards.add(c);
        }
        return cards;
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
