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

import static dev.predmon.forecast.ForecastFileSections.calibration;
import static dev.predmon.forecast.ForecastFileSections.count;
import static dev.predmon.forecast.ForecastFileSections.doubles;
import static dev.predmon.forecast.ForecastFileSections.integer;
import static dev.predmon.forecast.ForecastFileSections.number;
import static dev.predmon.forecast.ForecastFileSections.numbers;
import static dev.predmon.forecast.ForecastFileSections.readDeadlines;
import static dev.predmon.forecast.ForecastFileSections.readObligations;
import static dev.predmon.forecast.ForecastFileSections.required;
import static dev.predmon.forecast.ForecastFileSections.writeCalibration;
import static dev.predmon.forecast.ForecastFileSections.writeObligations;
import static dev.predmon.forecast.ScorecardJson.readScorecards;
import static dev.predmon.forecast.ScorecardJson.writeScorecards;

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
        body(root, m);
        if (!m.bounds().isEmpty()) {
            ObjectNode bounds = root.putObject("bounds");
            new TreeMap<>(m.bounds()).forEach((id, b) -> {
                ObjectNode n = bounds.putObject(id);
                n.put("side", b.side());
                body(n, b.model());
            });
        }
        writeEvents(root, m.events());
        try {
            return JSON.writeValueAsString(root) + "\n";
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a JSON tree does not write", e);
        }
    }

    /** Everything of {@code m} but its format and unit, into {@code root}. */
    private static void body(ObjectNode root, ForecastModel m) {
        number(root, "limit", m.limit());
        root.put("runs", m.runs());
        root.put("violating", m.violating());
        root.put("threshold", m.threshold());
        root.put("thresholdNote", m.thresholdNote());
        root.put("thresholdValidated", m.validated());
        ForecastFileSections.writeClauses(root, m.clauses());
        writeCalibration(root, m.calibration());
        writeScorecards(root, m.scorecards());
        writeObligations(root, m.obligations(), m.deadlines());
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
        String unit = required(root, "unit").asText();
        ForecastModel m = body(root, format, unit);
        m = m.withEvents(readEvents(root, format, unit));
        JsonNode bounds = root.get("bounds");
        if (bounds == null) {
            return m;
        }
        if (!bounds.isObject()) {
            throw new IllegalArgumentException("'bounds': expected an object");
        }
        Map<String, BoundModel> read = new TreeMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = bounds.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            try {
                if (!e.getValue().isObject()) {
                    throw new IllegalArgumentException("expected an object");
                }
                read.put(e.getKey(), new BoundModel(required(e.getValue(), "side").asText(),
                        body(e.getValue(), format, unit)));
            } catch (IllegalArgumentException x) {
                throw new IllegalArgumentException("'bounds/" + e.getKey() + "': " + x.getMessage(), x);
            }
        }
        return m.withBounds(read);
    }

    /**
     * The optional {@code events}: by absence or precedence id, its forecast as a bound's is written, or without one
     * the counts that say why ({@link EventModel#why}).
     */
    private static void writeEvents(ObjectNode root, Map<String, EventModel> events) {
        if (events.isEmpty()) {
            return;
        }
        ObjectNode all = root.putObject("events");
        new TreeMap<>(events).forEach((id, e) -> {
            ObjectNode n = all.putObject(id);
            if (e.forecasts()) {
                body(n, e.model());
            } else {
                n.put("runs", e.runs());
                n.put("violating", e.violating());
                n.put("noForecast", e.why());
            }
        });
    }

    private static Map<String, EventModel> readEvents(JsonNode root, int format, String unit) {
        JsonNode events = root.get("events");
        Map<String, EventModel> read = new TreeMap<>();
        if (events == null) {
            return read;
        }
        if (!events.isObject()) {
            throw new IllegalArgumentException("'events': expected an object");
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = events.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            String at = "events/" + e.getKey();
            try {
                JsonNode n = e.getValue();
                if (!n.isObject()) {
                    throw new IllegalArgumentException("expected an object");
                }
                if (n.has("states")) {
                    ForecastModel m = body(n, format, unit);
                    read.put(e.getKey(), new EventModel(m.runs(), m.violating(), m));
                } else {
                    read.put(e.getKey(), new EventModel(count(n, "runs", null), count(n, "violating", null), null));
                }
            } catch (IllegalArgumentException x) {
                throw new IllegalArgumentException("'" + at + "': " + x.getMessage(), x);
            }
        }
        return read;
    }

    /** The model {@link #body(ObjectNode, ForecastModel)} wrote into {@code root}. */
    private static ForecastModel body(JsonNode root, int format, String unit) {
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
            calibration = calibration(c, "calibration");
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
        return new ForecastModel(format, unit, number(root, "limit"),
                runs, violating, lows(root), threshold,
                required(root, "thresholdNote").asText(), required(root, "thresholdValidated").asBoolean(), states,
                starts, calibration, readScorecards(root), readObligations(root), readDeadlines(root))
                .withClauses(ForecastFileSections.readClauses(root));
    }

    /** One scorecard as {@code forecast.json} holds it (and {@code /status} shows it). */
    public static ObjectNode scorecard(Scorecard c) {
        return ScorecardJson.scorecard(c);
    }

    private static void lows(ObjectNode n, Lows lows) {
        numbers(n.putArray("safeLows"), lows.safe());
        numbers(n.putArray("violatingLows"), lows.violating());
    }

    private static Lows lows(JsonNode n) {
        return new Lows(doubles(required(n, "safeLows")), doubles(required(n, "violatingLows")));
    }

}
