package dev.predmon.forecast;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import static dev.predmon.forecast.JsonAt.number;
import static dev.predmon.forecast.JsonAt.numbers;

/**
 * The parts of {@code forecast.json} that entries of several kinds and both formats share ({@link ForecastFile}): a
 * value forecast's body (its rule, calibration, scorecards, lows and per-state tables), a deadline forecast's training
 * obligations and rule. Every part added after the first format is optional, so that an older file still reads. Each
 * range is checked once: here where the type does not check it itself, else by the type's constructor
 * ({@link JsonAt#built}), told at the value's path.
 */
final class ForecastFileSections {

    private ForecastFileSections() {
    }

    /** A value forecast's own parts into {@code n}: everything but its format, unit and the other properties. */
    static void writeBody(ObjectNode n, ForecastModel m) {
        number(n, "limit", m.limit());
        n.put("runs", m.runs());
        n.put("violating", m.violating());
        n.put("threshold", m.threshold());
        n.put("thresholdNote", m.thresholdNote());
        n.put("thresholdValidated", m.validated());
        writeClauses(n, m.clauses());
        writeCalibration(n, m.calibration());
        ScorecardJson.writeScorecards(n, m.scorecards());
        writeRest(n, m);
    }

    /** The start inputs, the lows and the per-state tables of {@code m}. */
    static void writeRest(ObjectNode n, ForecastModel m) {
        ArrayNode starts = n.putArray("startInputs");
        m.startInputs().forEach(starts::add);
        lows(n, m.lows());
        ObjectNode machines = n.putObject("states");
        new TreeMap<>(m.states()).forEach((id, table) -> {
            ObjectNode states = machines.putObject(id);
            new TreeMap<>(table).forEach((state, s) -> {
                ObjectNode o = states.putObject(Integer.toString(state));
                o.put("runs", s.runs());
                o.put("violated", s.violated());
                numbers(o.putArray("toViolation"), new double[] {s.toViolationLow(), s.toViolationMedian(),
                        s.toViolationHigh()});
                number(o, "toEnd", s.toEnd());
                number(o, "drift", s.drift());
                number(o, "driftSpread", s.driftSpread());
                o.put("driftRuns", s.driftRuns());
                lows(o, s.lows());
            });
        });
    }

    /** The value forecast {@link #writeBody} wrote at {@code n}, its times in {@code unit}. */
    static ForecastModel readBody(JsonAt n, int format, String unit) {
        Map<String, Map<Integer, StateStats>> states = new TreeMap<>();
        for (Map.Entry<String, JsonAt> machine : n.get("states").members().entrySet()) {
            Map<Integer, StateStats> table = new TreeMap<>();
            for (Map.Entry<String, JsonAt> e : machine.getValue().members().entrySet()) {
                JsonAt s = e.getValue().object();
                int state;
                try {
                    state = Integer.parseInt(e.getKey());
                } catch (NumberFormatException x) {
                    throw machine.getValue().wrong("'" + e.getKey() + "' is not a state number");
                }
                double[] tv = s.doubles("toViolation");
                if (tv.length != 3) {
                    throw s.get("toViolation").wrong("expected 3 numbers");
                }
                int runs = s.count("runs");
                int violated = s.count("violated");
                double toEnd = s.number("toEnd");
                double drift = s.number("drift");
                double spread = s.number("driftSpread");
                int driftRuns = s.count("driftRuns");
                Lows lows = lows(s);
                table.put(state, s.built(() -> new StateStats(runs, violated, tv[0], tv[1], tv[2], toEnd, drift,
                        spread, driftRuns, lows)));
            }
            states.put(machine.getKey(), table);
        }
        JsonAt startNode = n.get("startInputs");
        if (!startNode.node().isArray()) {
            throw startNode.wrong("expected an array of inputs");
        }
        List<String> starts = new ArrayList<>();
        startNode.node().forEach(s -> starts.add(s.asText()));
        JsonAt c = n.optional("calibration");
        Calibration calibration = c == null ? Calibration.IDENTITY : calibration(c);
        int runs = n.count("runs");
        int violating = n.count("violating");
        if (violating > runs) {
            throw n.get("violating").wrong(violating + " of " + runs + " runs");
        }
        double threshold = n.number("threshold");
        if (!(threshold >= 0 && threshold <= 1)) {
            throw n.get("threshold").wrong(n.get("threshold").node() + " is not a probability (from 0 to 1)");
        }
        return new ForecastModel(format, unit, n.number("limit"), runs, violating, lows(n), threshold,
                n.text("thresholdNote"), n.bool("thresholdValidated"), states, starts, calibration,
                ScorecardJson.readScorecards(n)).withClauses(readClauses(n));
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

    /** The calibration object at {@code c}. */
    static Calibration calibration(JsonAt c) {
        c.object();
        double slope = c.number("slope");
        if (!(slope > 0)) {
            throw c.get("slope").wrong("expected a positive number");
        }
        double intercept = c.number("intercept");
        if (Double.isNaN(intercept)) {
            throw c.get("intercept").wrong("expected a number");
        }
        return new Calibration(slope, intercept, c.count("runs"));
    }

    /** A deadline forecast's training obligations into {@code n}: pooled, and by trigger input when learned so. */
    static void writeSurvival(ObjectNode n, Survival survival) {
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
    }

    /** The training obligations {@link #writeSurvival} wrote at {@code n}. */
    static Survival readSurvival(JsonAt n) {
        n.object();
        Survival pooled = new Survival(n.doubles("discharged"), n.doubles("censored"));
        JsonAt by = n.optional("byInput");
        if (by == null) {
            return pooled;
        }
        Map<String, Survival> contexts = new TreeMap<>();
        for (Map.Entry<String, JsonAt> c : by.members().entrySet()) {
            JsonAt s = c.getValue().object();
            contexts.put(c.getKey(), new Survival(s.doubles("discharged"), s.doubles("censored")));
        }
        return pooled.withContexts(contexts);
    }

    /** When a deadline forecast warns, into {@code n}: nothing for a property without a learned rule. */
    static void writeRule(ObjectNode n, DeadlineRule rule) {
        if (rule == null) {
            return;
        }
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

    /**
     * The rule {@link #writeRule} wrote at {@code n}, null without a {@code threshold}. The threshold's and the
     * margin's ranges are {@link DeadlineRule}'s own, each told at its key.
     */
    static DeadlineRule readRule(JsonAt n) {
        if (!n.has("threshold")) {
            return null;
        }
        double threshold = n.number("threshold");
        double margin = n.has("margin") ? n.number("margin") : DeadlineRule.HALF;
        n.get("threshold").built(() -> new DeadlineRule(threshold, "", false, Calibration.IDENTITY,
                DeadlineRule.HALF, false));
        if (n.has("margin")) {
            n.get("margin").built(() -> new DeadlineRule(DeadlineRule.NEVER, "", false, Calibration.IDENTITY,
                    margin, false));
        }
        double level = n.has("level") ? n.number("level") : Double.NaN;
        if (n.has("level")) {
            n.get("level").built(() -> new DeadlineRule(DeadlineRule.NEVER, "", false, Calibration.IDENTITY,
                    DeadlineRule.HALF, false, level));
        }
        JsonAt ceiling = n.optional("lateCeiling");
        if (ceiling != null && !(ceiling.node().isTextual() && ceiling.node().asText().equals("every"))) {
            throw ceiling.wrong("expected \"every\"");
        }
        boolean validated = n.bool("validated");
        JsonAt rule = n.optional("rule");
        if (rule != null && !(rule.node().isTextual() && rule.node().asText().equals("baseline"))) {
            throw rule.wrong("expected \"baseline\"");
        }
        JsonAt c = n.optional("calibration");
        return new DeadlineRule(threshold, n.text("note"), validated, c == null ? Calibration.IDENTITY
                : calibration(c), margin, rule != null, level, ceiling != null);
    }

    /**
     * Which clauses warn ({@link Clauses}), written only when not every clause of the forecast's rule does, so that a
     * file learned before the choice reads as it did: {@code "rule": "baseline"} for the raw-value baseline,
     * {@code "matching": false} for the forecast's rule without the thesis's matching.
     */
    static void writeClauses(ObjectNode n, Clauses c) {
        if (c.baseline()) {
            n.put("rule", "baseline");
        } else if (!c.matching()) {
            n.put("matching", false);
        }
    }

    /** The clauses of {@link #writeClauses}: every clause when neither key is there. */
    static Clauses readClauses(JsonAt n) {
        JsonAt rule = n.optional("rule");
        if (rule != null && !(rule.node().isTextual() && (rule.node().asText().equals("baseline")
                || rule.node().asText().equals("forecast")))) {
            throw rule.wrong("expected \"baseline\" or \"forecast\"");
        }
        boolean matching = !n.has("matching") || n.bool("matching");
        if (rule != null && rule.node().asText().equals("baseline")) {
            return Clauses.BASELINE;
        }
        return matching ? Clauses.ALL : Clauses.NO_MATCHING;
    }

    private static void lows(ObjectNode n, Lows lows) {
        numbers(n.putArray("safeLows"), lows.safe());
        numbers(n.putArray("violatingLows"), lows.violating());
    }

    private static Lows lows(JsonAt n) {
        return new Lows(n.doubles("safeLows"), n.doubles("violatingLows"));
    }
}
