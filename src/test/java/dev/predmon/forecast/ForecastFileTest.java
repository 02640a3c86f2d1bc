package dev.predmon.forecast;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code forecast.json} of format 2: one entry per property, in the abstraction's order, each with its kind and
 * everything its forecast needs; the first floor is a bound like any other. Every kind reads back as written, a model
 * is the same whichever way it is seen (per property or as the top level and side maps), and a file of format 1 still
 * reads.
 */
class ForecastFileTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Scorecard BATTERY_CARD = new Scorecard("battery >= 20", 5, 30, 10, 9, 1, 8.5, "s", 0.19, 0.22);
    private static final Scorecard NAV_CARD = new Scorecard("a navigation ends within 400 ticks", 5, 40, 2, 2, 0, 60,
            "ticks", 0.05, 0.1, Scorecard.OBLIGATIONS);

    /** A value forecast of {@code runs} runs, {@code violating} of them violating, with a limit and a threshold. */
    private static ForecastModel value(double limit, int runs, int violating, double threshold, List<Scorecard> cards) {
        return new ForecastModel(ForecastModel.FORMAT, "s", limit, runs, violating,
                new Lows(new double[] {limit + 10, limit + 20}, new double[] {limit + 1}), threshold, "chosen by hand",
                true, Map.of("direct", Map.of(0, new StateStats(runs, violating, 1, 2, 3, 40, -0.5, 0.1, 3,
                new Lows(new double[] {limit + 10}, new double[] {limit + 1})))), List.of("level_i"),
                new Calibration(1.2, -0.3, runs), cards);
    }

    /** One property of every kind, as learn gives them, in an abstraction's order. */
    private static List<PropertyModel> everyKind() {
        Survival navigations = new Survival(new double[] {4, 5, 10}, new double[] {1}).withContexts(Map.of());
        return List.of(
                new PropertyModel.OfBound("hot", new BoundModel(BoundModel.CEILING, value(-70, 30, 4, 0.4, List.of()))),
                new PropertyModel.OfBound("battery", new BoundModel(BoundModel.FLOOR, value(20, 30, 10, 0.9,
                        List.of(BATTERY_CARD)).withClauses(Clauses.BASELINE))),
                new PropertyModel.OfDeadline("navigation-in-time", navigations, new DeadlineRule(0.7, "n", true,
                        new Calibration(1.1, 0.1, 40), 0, false), List.of(NAV_CARD)),
                new PropertyModel.OfDeadline("grasp-in-time", new Survival(new double[0], new double[0]), null,
                        List.of()),
                new PropertyModel.OfEvent("no-abort", new EventModel(30, 10, value(EventModel.HOLDS, 30, 10, 0.69,
                        List.of()).withClauses(Clauses.NO_MATCHING))),
                new PropertyModel.OfBound("reserve", new BoundModel(BoundModel.FLOOR, value(40, 30, 12, 0.5,
                        List.of()))),
                new PropertyModel.OfEvent("ready-first", new EventModel(43, 0, null)));
    }

    @Test
    void everyKindReadsBackAsWrittenInTheAbstractionsOrder() throws Exception {
        ForecastModel m = ForecastModel.of("s", 30, everyKind());
        assertEquals("battery", m.first(), "the first bound forecast on its floor: a ceiling before it is not");
        assertEquals(20.0, m.limit());
        assertEquals(List.of("hot", "reserve"), List.copyOf(new TreeMap<>(m.bounds()).keySet()));
        assertEquals(everyKind(), m.properties(), "the same properties, kind by kind, in order");

        String text = ForecastFile.write(m, "sha256:00");
        ForecastModel back = ForecastFile.read(text, "sha256:00");
        assertEquals(m, back);
        assertEquals(text, ForecastFile.write(back, "sha256:00"), "the same model gives the same bytes");

        JsonNode file = JSON.readTree(text);
        assertEquals(List.of("format", "learnId", "unit", "runs", "properties"), names(file));
        assertEquals(2, file.get("format").asInt());
        JsonNode p = file.get("properties");
        assertEquals(List.of("hot", "battery", "navigation-in-time", "grasp-in-time", "no-abort", "reserve",
                "ready-first"), names(p));
        assertEquals(List.of("bound", "bound", "deadline", "deadline", "event", "bound", "event"),
                names(p).stream().map(id -> p.get(id).get("kind").asText()).toList());
        assertEquals(names(p.get("reserve")), names(p.get("battery")).stream()
                .filter(k -> !k.equals("rule") && !k.equals("scorecards")).toList(), "the first floor is written as any other bound");
        assertEquals("floor", p.get("battery").get("side").asText());
        assertEquals("baseline", p.get("battery").get("rule").asText());
        assertEquals("obligations", p.get("navigation-in-time").get("scorecards").get(0).get("counted").asText());
        assertFalse(p.get("grasp-in-time").has("threshold"), "no rule learned: none written");
        assertEquals("never violated in 43 training runs", p.get("ready-first").get("noForecast").asText());

        assertInstanceOf(PropertyModel.OfDeadline.class, back.property("navigation-in-time").orElseThrow());
        assertEquals(DeadlineRule.DEFAULT, ((PropertyModel.OfDeadline) back.property("grasp-in-time").orElseThrow())
                .warnsBy());
        assertEquals(List.of(BATTERY_CARD), back.property("battery").orElseThrow().scorecards());
        assertEquals(List.of(BATTERY_CARD, NAV_CARD), back.allScorecards(), "the first floor's, then the deadlines'");
        assertTrue(back.property("speed").isEmpty());
    }

    /** Without a first floor, nothing is forecast at the top level, and nothing of it is written. */
    @Test
    void aModelWithoutAFirstFloor() {
        List<PropertyModel> some = everyKind().stream().filter(p -> !(p instanceof PropertyModel.OfBound b
                && !b.model().mirrored())).toList();
        ForecastModel m = ForecastModel.of("s", 12, some);
        assertNull(m.first());
        assertTrue(Double.isNaN(m.limit()));
        assertEquals(12, m.runs());
        assertFalse(m.validated(), "no first floor: the forecast rule is never the default");
        assertEquals(some, m.properties());
        String text = ForecastFile.write(m);
        assertEquals(m, ForecastFile.read(text));
        assertFalse(text.contains("\"side\" : \"floor\""), text);
    }

    @Test
    void aFirstFloorWithoutItsIdIsNotWritten() {
        ForecastModel unnamed = value(20, 30, 10, 0.9, List.of());
        assertThrows(IllegalStateException.class, () -> ForecastFile.write(unnamed));
    }

    /** Two entries of one property, or an entry of no known kind, are refused where they are. */
    @Test
    void anEntryOfNoKnownKind() throws Exception {
        ObjectNode f = (ObjectNode) JSON.readTree(ForecastFile.write(ForecastModel.of("s", 30, everyKind())));
        ((ObjectNode) f.get("properties").get("reserve")).put("kind", "floor");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(JSON.writeValueAsString(f)));
        assertEquals("'properties.reserve.kind': 'floor', expected one of bound, deadline, event", e.getMessage());
        ((ObjectNode) f.get("properties").get("reserve")).remove("kind");
        e = assertThrows(IllegalArgumentException.class, () -> ForecastFile.read(JSON.writeValueAsString(f)));
        assertEquals("'properties.reserve.kind' is missing", e.getMessage());
    }

    /**
     * A file of format 1 (the shipped models' before format 2) reads as it did; named with its abstraction, its first
     * floor is the abstraction's, and a deadline's scorecard kept beside the first floor's goes to its property.
     */
    @Test
    void aFileOfFormat1ReadsAndIsNamedByItsAbstraction() throws Exception {
        Path dir = Path.of("src/test/resources/forecast/format-1");
        ObjectNode old = (ObjectNode) JSON.readTree(dir.resolve(ForecastFile.NAME).toFile());
        assertEquals(1, old.get("format").asInt());
        ((ArrayNode) old.get("scorecards")).add(JSON.valueToTree(Map.of("property", NAV_CARD.property(), "folds", 5,
                "runs", 40, "violating", 2, "warned", 2, "falseAlarms", 0, "medianLead", 60, "unit", "ticks",
                "brier", 0.05, "baseBrier", 0.1)).deepCopy());
        ((ObjectNode) old.get("scorecards").get(1)).put("counted", Scorecard.OBLIGATIONS);
        ForecastModel read = ForecastFile.read(JSON.writeValueAsString(old));
        assertEquals(ForecastModel.FORMAT_1, read.format());
        assertNull(read.first(), "format 1 does not say which property the top level forecasts");
        assertEquals(20.0, read.limit());
        assertEquals(2, read.scorecards().size());

        Abstraction abstraction = AbstractionFiles.load(dir.resolve("abstraction.json"));
        ForecastModel named = PropertyParts.named(read, abstraction);
        assertEquals("battery", named.first());
        assertEquals(List.of("battery", "charger-in-time", "navigation-in-time", "grasp-in-time"),
                named.properties().stream().map(PropertyModel::id).toList(), "in the abstraction's order");
        assertEquals(List.of(NAV_CARD), named.property("navigation-in-time").orElseThrow().scorecards());
        assertEquals(1, named.property("battery").orElseThrow().scorecards().size());
        assertEquals(read.allScorecards(), named.allScorecards(), "the same cards, in the same order");

        ForecastModel again = ForecastFile.read(ForecastFile.write(named));
        assertEquals(named.properties().stream().map(PropertyModel::id).toList(),
                again.properties().stream().map(PropertyModel::id).toList());
        assertEquals(named.threshold(), again.threshold());
        assertEquals(named.obligations(), again.obligations());
        assertEquals(named.deadlines(), again.deadlines());
    }

    private static List<String> names(JsonNode n) {
        List<String> out = new ArrayList<>();
        n.fieldNames().forEachRemaining(out::add);
        return out;
    }
}
