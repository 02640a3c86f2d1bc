package dev.predmon.forecast;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.file.LocatedJson;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The text of {@code forecast.json}: a {@link ForecastModel} as JSON, numbers that are not known written as
 * {@code null} (JSON has no NaN), keys in a fixed order so that the same training runs give the same bytes.
 *
 * <p>Format {@value ForecastModel#FORMAT}, the one written: after {@code format}, {@code learnId}, {@code unit} and
 * {@code runs} (the training runs), {@code properties} holds one entry per property the forecast learned something
 * for, keyed by its id in the abstraction's order, each {@code {"kind": "bound" | "deadline" | "event", ...}} with
 * everything that property's forecast needs ({@link PropertyCodec}); the abstraction's first floor is a bound like any
 * other. Format 1 (the first floor at the top level, the other properties in side maps) is still read
 * ({@link ForecastFileOne}).
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

    /** The top-level keys of the format written; every other part is a property's, under {@code properties}. */
    private static final Set<String> TOP = Set.of("format", LEARN_ID, "unit", "runs", "properties");

    /**
     * The JSON text of {@code m} with the learn id of the models it was learned with (none when null), in the format
     * {@value ForecastModel#FORMAT} whatever format {@code m} was read from.
     *
     * @throws IllegalStateException when {@code m} forecasts a first floor it does not name ({@link PropertyParts#named})
     */
    public static String write(ForecastModel m, String learnId) {
        if (m.first() == null && !Double.isNaN(m.limit())) {
            throw new IllegalStateException("the forecast of a first floor (limit " + m.limit() + ") without its "
                    + "property's id: name its properties with the abstraction before writing it");
        }
        ObjectNode root = JSON.createObjectNode();
        root.put("format", ForecastModel.FORMAT);
        if (learnId != null) {
            root.put(LEARN_ID, learnId);
        }
        root.put("unit", m.unit());
        root.put("runs", m.runs());
        ObjectNode properties = root.putObject("properties");
        m.properties().forEach(p -> PropertyCodec.write(properties, p));
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

    private static ForecastModel read(JsonNode node) {
        JsonAt root = JsonAt.root(node);
        int format = root.integer("format");
        if (format == ForecastModel.FORMAT_1) {
            return ForecastFileOne.read(root);
        }
        if (format != ForecastModel.FORMAT) {
            throw root.get("format").wrong(format + ", expected " + ForecastModel.FORMAT_1 + " or "
                    + ForecastModel.FORMAT);
        }
        for (Map.Entry<String, JsonAt> e : root.members().entrySet()) {
            if (!TOP.contains(e.getKey())) {
                throw e.getValue().wrong("not a key of format " + format + ", where each property's forecast is "
                        + "under 'properties'");
            }
        }
        String unit = root.text("unit");
        int runs = root.count("runs");
        List<PropertyModel> properties = new ArrayList<>();
        JsonAt all = root.get("properties");
        for (Map.Entry<String, JsonAt> e : all.members().entrySet()) {
            properties.add(PropertyCodec.read(e.getKey(), e.getValue(), unit));
        }
        ForecastModel m = all.built(() -> ForecastModel.of(unit, runs, properties));
        if (m.runs() != runs) {
            throw root.get("runs").wrong(runs + ", but the first floor '" + m.first() + "' counts " + m.runs()
                    + " training runs");
        }
        return m;
    }

    /** One scorecard as {@code forecast.json} holds it (and {@code /status} shows it). */
    public static ObjectNode scorecard(Scorecard c) {
        return ScorecardJson.scorecard(c);
    }

}
