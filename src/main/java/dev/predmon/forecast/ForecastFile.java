package dev.predmon.forecast;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.file.LocatedJson;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The text of {@code forecast.json}: a {@link ForecastModel} as JSON, numbers that are not known written as
 * {@code null} (JSON has no NaN), keys in a fixed order so that the same training runs give the same bytes.
 */
public final class ForecastFile {

    /** The file's name in a model directory. */
    public static final String NAME = "forecast.json";

    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private ForecastFile() {
    }

    /** The key of the learn id: what ties the file to the index and DOT files it was learned with. */
    private static final String LEARN_ID = "learnId";

    /** The JSON text of {@code m}, ending with a newline. */
    public static String write(ForecastModel m) {
        return write(m, null);
    }

    /** The JSON text of {@code m} with the learn id of the models it was learned with (none when null). */
    public static String write(ForecastModel m, String learnId) {
        ObjectNode root = JSON.createObjectNode();
        root.put("format", m.format());
        if (learnId != null) {
            root.put(LEARN_ID, learnId);
        }
        root.put("unit", m.unit());
        number(root, "limit", m.limit());
        root.put("runs", m.runs());
        root.put("violating", m.violating());
        root.put("threshold", m.threshold());
        root.put("thresholdNote", m.thresholdNote());
        root.put("thresholdValidated", m.validated());
        if (m.calibration().runs() > 0) {
            ObjectNode c = root.putObject("calibration");
            c.put("slope", m.calibration().slope());
            c.put("intercept", m.calibration().intercept());
            c.put("runs", m.calibration().runs());
        }
        writeScorecards(root, m.scorecards());
        if (!m.obligations().isEmpty()) {
            ObjectNode o = root.putObject("obligations");
            new TreeMap<>(m.obligations()).forEach((id, survival) -> {
                ObjectNode n = o.putObject(id);
                numbers(n.putArray("discharged"), survival.discharged());
                numbers(n.putArray("censored"), survival.censored());
            });
        }
        ArrayNode starts = root.putArray("startInputs");
        m.startInputs().forEach(starts::add);
        lows(root, m.lows());
        ObjectNode machines = root.putObject("states");
        new TreeMap<>(m.states()).forEach((id, table) -> {
            ObjectNode states = machines.putObject(id);
            new TreeMap<>(table).forEach((state, s) -> {
                ObjectNode n = states.putObject(Integer.toString(state));
                n.put("runs", s.runs());
                n.put("violated", s.violated());
                numbers(n.putArray("toViolation"), new double[] {s.toViolationLow(), s.toViolationMedian(),
                        s.toViolationHigh()});
                number(n, "toEnd", s.toEnd());
                number(n, "drift", s.drift());
                number(n, "driftSpread", s.driftSpread());
                n.put("driftRuns", s.driftRuns());
                lows(n, s.lows());
            });
        });
        try {
            return JSON.writeValueAsString(root) + "\n";
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a JSON tree does not write", e);
        }
    }

    /**
     * Reads what {@link #write} wrote, whatever its learn id.
     *
     * @throws IllegalArgumentException with what is wrong, when the text is not such a file
     */
    public static ForecastModel read(String text) {
        return read(parse(text));
    }

    /**
     * Reads what {@link #write} wrote for the models of {@code learnId}.
     *
     * @throws IllegalArgumentException with what is wrong, when the text is not such a file or was learned with
     *                                  other models
     */
    public static ForecastModel read(String text, String learnId) {
        JsonNode root = parse(text);
        JsonNode id = root.get(LEARN_ID);
        if (id == null || !id.isTextual()) {
            throw new IllegalArgumentException("it has no learn id, so it cannot be tied to the models beside it");
        }
        if (!id.textValue().equals(learnId)) {
            throw new IllegalArgumentException("learned with other models than the index lists (learn id "
                    + abbreviated(id.textValue()) + ", the index's " + abbreviated(learnId)
                    + "); the directory mixes files of different learns");
        }
        return read(root);
    }

    private static String abbreviated(String id) {
        return id.length() > 19 ? id.substring(0, 19) + "..." : id;
    }

    /**
     * The JSON object of {@code text}, read with the limits of every predmon file ({@link LocatedJson}): a file
     * nested too deep or holding a number or string far too long is one line, not a crash.
     */
    private static JsonNode parse(String text) {
        JsonNode root;
        try {
            root = LocatedJson.parse(text).root();
        } catch (JsonProcessingException e) {
            JsonLocation l = e.getLocation();
            throw new IllegalArgumentException((l == null ? "" : "line " + l.getLineNr() + ": ") + "not JSON: "
                    + e.getOriginalMessage());
        } catch (IOException e) {
            throw new IllegalArgumentException("not JSON: " + e.getMessage());
        }
        if (root == null || !root.isObject()) {
            throw new IllegalArgumentException("expected a JSON object");
        }
        return root;
    }

    private static ForecastModel read(JsonNode root) {
        int format = integer(root, "format");
        if (format != ForecastModel.FORMAT) {
            throw new IllegalArgumentException("format " + format + ", expected " + ForecastModel.FORMAT);
        }
        Map<String, Map<Integer, StateStats>> states = new TreeMap<>();
        JsonNode machines = required(root, "states");
        for (Iterator<Map.Entry<String, JsonNode>> it = machines.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> machine = it.next();
            Map<Integer, StateStats> table = new TreeMap<>();
            for (Iterator<Map.Entry<String, JsonNode>> st = machine.getValue().fields(); st.hasNext(); ) {
                Map.Entry<String, JsonNode> e = st.next();
                JsonNode n = e.getValue();
                double[] tv = doubles(required(n, "toViolation"));
                if (tv.length != 3) {
                    throw new IllegalArgumentException("states/" + machine.getKey() + "/" + e.getKey()
                            + "/toViolation: expected 3 numbers");
                }
                int state;
                try {
                    state = Integer.parseInt(e.getKey());
                } catch (NumberFormatException x) {
                    throw new IllegalArgumentException("states/" + machine.getKey() + ": '" + e.getKey()
                            + "' is not a state number");
                }
                String at = "states/" + machine.getKey() + "/" + e.getKey();
                int runs = count(n, "runs", at);
                int violated = count(n, "violated", at);
                if (violated > runs) {
                    throw new IllegalArgumentException("'" + at + "': " + violated + " violated of " + runs
                            + " runs");
                }
                table.put(state, new StateStats(runs, violated, tv[0], tv[1], tv[2], number(n, "toEnd"),
                        number(n, "drift"), number(n, "driftSpread"), count(n, "driftRuns", at), lows(n)));
            }
            states.put(machine.getKey(), table);
        }
        List<String> starts = new ArrayList<>();
        required(root, "startInputs").forEach(s -> starts.add(s.asText()));
        Calibration calibration = Calibration.IDENTITY;
        JsonNode c = root.get("calibration");
        if (c != null) {
            double slope = number(c, "slope");
            if (!(slope > 0)) {
                throw new IllegalArgumentException("'calibration/slope': expected a positive number");
            }
            double intercept = number(c, "intercept");
            if (Double.isNaN(intercept)) {
                throw new IllegalArgumentException("'calibration/intercept': expected a number");
            }
            calibration = new Calibration(slope, intercept, count(c, "runs", "calibration"));
        }
        int runs = count(root, "runs", null);
        int violating = count(root, "violating", null);
        if (violating > runs) {
            throw new IllegalArgumentException("'violating': " + violating + " of " + runs + " runs");
        }
        double threshold = number(root, "threshold");
        if (!(threshold >= 0 && threshold <= 1)) {
            throw new IllegalArgumentException("'threshold': " + root.get("threshold")
                    + " is not a probability (from 0 to 1)");
        }
        return new ForecastModel(format, required(root, "unit").asText(), number(root, "limit"),
                runs, violating, lows(root), threshold,
                required(root, "thresholdNote").asText(), required(root, "thresholdValidated").asBoolean(), states,
                starts, calibration, readScorecards(root), readObligations(root));
    }

    /** The optional {@code obligations}: per bounded-response property, the training obligations' durations. */
    private static Map<String, Survival> readObligations(JsonNode root) {
        Map<String, Survival> obligations = new TreeMap<>();
        JsonNode o = root.get("obligations");
        if (o == null) {
            return obligations;
        }
        if (!o.isObject()) {
            throw new IllegalArgumentException("'obligations': expected an object");
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = o.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            try {
                obligations.put(e.getKey(), new Survival(doubles(required(e.getValue(), "discharged")),
                        doubles(required(e.getValue(), "censored"))));
            } catch (IllegalArgumentException x) {
                throw new IllegalArgumentException("'obligations/" + e.getKey() + "': " + x.getMessage(), x);
            }
        }
        return obligations;
    }

    /** The optional {@code scorecards} list: one object per property, written only when there is one. */
    private static void writeScorecards(ObjectNode root, List<Scorecard> cards) {
        if (cards.isEmpty()) {
            return;
        }
        ArrayNode a = root.putArray("scorecards");
        cards.forEach(c -> a.add(scorecard(c)));
    }

    /** One scorecard as {@code forecast.json} holds it (and {@code /status} shows it). */
    public static ObjectNode scorecard(Scorecard c) {
        ObjectNode n = JSON.createObjectNode();
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
        return n;
    }

    private static List<Scorecard> readScorecards(JsonNode root) {
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
                    required(n, "unit").asText(), number(n, "brier"), number(n, "baseBrier"));
            if (c.runs() < 0 || c.violating() < 0 || c.violating() > c.runs() || c.warned() < 0
                    || c.warned() > c.violating() || c.falseAlarms() < 0 || c.falseAlarms() > c.held()) {
                throw new IllegalArgumentException("'scorecards' of '" + c.property() + "': expected 0 <= warned <= "
                        + "violating <= runs and 0 <= falseAlarms <= runs - violating");
            }
            if (!(c.brier() >= 0 && c.brier() <= 1) || !(c.baseBrier() >= 0 && c.baseBrier() <= 1)) {
                throw new IllegalArgumentException("'scorecards' of '" + c.property() + "': expected Brier scores "
                        + "between 0 and 1");
            }
            cards.add(c);
        }
        return cards;
    }

    private static void lows(ObjectNode n, Lows lows) {
        numbers(n.putArray("safeLows"), lows.safe());
        numbers(n.putArray("violatingLows"), lows.violating());
    }

    private static Lows lows(JsonNode n) {
        return new Lows(doubles(required(n, "safeLows")), doubles(required(n, "violatingLows")));
    }

    private static void number(ObjectNode n, String key, double v) {
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            n.putNull(key);
        } else {
            n.put(key, v);
        }
    }

    private static void numbers(ArrayNode a, double[] values) {
        for (double v : values) {
            if (Double.isNaN(v) || Double.isInfinite(v)) {
                a.addNull();
            } else {
                a.add(v);
            }
        }
    }

    private static JsonNode required(JsonNode n, String key) {
        JsonNode v = n.get(key);
        if (v == null) {
            throw new IllegalArgumentException("'" + key + "' is missing");
        }
        return v;
    }

    private static int integer(JsonNode n, String key) {
        JsonNode v = required(n, key);
        if (!v.canConvertToInt() || !v.isIntegralNumber()) {
            throw new IllegalArgumentException("'" + key + "': expected a whole number");
        }
        return v.intValue();
    }

    /** A count: a whole number, 0 or more; {@code at} says where, null at the top. */
    private static int count(JsonNode n, String key, String at) {
        int v = integer(n, key);
        if (v < 0) {
            throw new IllegalArgumentException("'" + (at == null ? "" : at + "/") + key + "': " + v
                    + ", expected 0 or more");
        }
        return v;
    }

    private static double number(JsonNode n, String key) {
        JsonNode v = required(n, key);
        if (v.isNull()) {
            return Double.NaN;
        }
        if (!v.isNumber()) {
            throw new IllegalArgumentException("'" + key + "': expected a number or null");
        }
        return v.doubleValue();
    }

    private static double[] doubles(JsonNode a) {
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
