package dev.predmon.forecast;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

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

    /** The JSON text of {@code m}, ending with a newline. */
    public static String write(ForecastModel m) {
        ObjectNode root = JSON.createObjectNode();
        root.put("format", m.format());
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
     * Reads what {@link #write} wrote.
     *
     * @throws IllegalArgumentException with what is wrong, when the text is not such a file
     */
    public static ForecastModel read(String text) {
        JsonNode root;
        try {
            root = JSON.readTree(text);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException("line " + e.getLocation().getLineNr() + ": not JSON: "
                    + e.getOriginalMessage());
        }
        if (root == null || !root.isObject()) {
            throw new IllegalArgumentException("expected a JSON object");
        }
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
                table.put(state, new StateStats(integer(n, "runs"), integer(n, "violated"), tv[0], tv[1], tv[2],
                        number(n, "toEnd"), number(n, "drift"), number(n, "driftSpread"), integer(n, "driftRuns"),
                        lows(n)));
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
            calibration = new Calibration(slope, intercept, integer(c, "runs"));
        }
        return new ForecastModel(format, required(root, "unit").asText(), number(root, "limit"),
                integer(root, "runs"), integer(root, "violating"), lows(root), number(root, "threshold"),
                required(root, "thresholdNote").asText(), required(root, "thresholdValidated").asBoolean(), states,
                starts, calibration);
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
