package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.forecast.BoundModel;
import dev.predmon.forecast.ForecastFile;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.PropertyModel;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code forecast.json} of format 1 (the first floor at the top level, the other properties in side maps), as the
 * models shipped before format 2 hold it (a copy in {@code src/test/resources/forecast/format-1}), still reads: the
 * same models with their forecast rewritten in format 2 give the same forecasts and warnings, event for event, on every
 * sample log. And learn writes the same bytes for the same training runs.
 */
class ForecastFormatsCliTest {

    private static final Path FORMAT_1 = Path.of("src/test/resources/forecast/format-1");
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path tmp;

    private Path copy(Path from, String name) throws Exception {
        Path to = Files.createDirectories(tmp.resolve(name));
        try (Stream<Path> s = Files.list(from)) {
            for (Path p : s.toList()) {
                Files.copy(p, to.resolve(p.getFileName()));
            }
        }
        return to;
    }

    @Test
    void modelsOfFormat1WarnAsTheSameModelsRewrittenInFormat2() throws Exception {
        Path one = copy(FORMAT_1, "one");
        assertEquals(1, JSON.readTree(one.resolve(ForecastFile.NAME).toFile()).get("format").asInt());
        Abstraction abstraction = AbstractionFiles.load(one.resolve(ModelStore.ABSTRACTION));
        ModelSet read = ModelStore.read(one, abstraction);
        String learnId = read.index().learnId();
        Path two = copy(FORMAT_1, "two");
        String rewritten = ForecastFile.write(read.forecast(), learnId);
        Files.writeString(two.resolve(ForecastFile.NAME), rewritten);
        JsonNode file = JSON.readTree(rewritten);
        assertEquals(2, file.get("format").asInt());
        assertEquals(List.of("format", "learnId", "unit", "runs", "properties"), names(file));
        assertEquals(List.of("battery", "charger-in-time", "navigation-in-time", "grasp-in-time"),
                names(file.get("properties")), "every property learned, in the abstraction's order");
        assertEquals("floor", file.get("properties").get("battery").get("side").asText());

        ForecastModel f1 = read.forecast();
        ForecastModel f2 = ModelStore.read(two, abstraction).forecast();
        assertEquals(f1.properties(), withFormat1(f2.properties()), "every property's forecast, kind by kind");
        assertEquals(f1.allScorecards(), f2.allScorecards());

        Cli a = watch(one);
        Cli b = watch(two);
        assertEquals(a.code(), b.code(), a.err() + b.err());
        assertEquals(byLog(a.out()), byLog(b.out()), "the same forecasts and warnings, event for event");
        assertTrue(a.out().contains("\"event\":\"warning\""), "the depleted runs are warned: " + a.out());
        assertTrue(a.out().contains("\"event\":\"forecast\""), a.out());
    }

    /** The properties of a model read from format 2 as the same model read from format 1 holds them. */
    private static List<PropertyModel> withFormat1(List<PropertyModel> ps) {
        List<PropertyModel> out = new ArrayList<>();
        for (PropertyModel p : ps) {
            if (p instanceof PropertyModel.OfBound b) {
                ForecastModel m = b.model().model();
                out.add(new PropertyModel.OfBound(b.id(), new BoundModel(b.model().side(),
                        new ForecastModel(1, m.unit(), m.limit(), m.runs(), m.violating(), m.lows(), m.threshold(),
                                m.thresholdNote(), m.validated(), m.states(), m.startInputs(), m.calibration(),
                                m.scorecards()).withClauses(m.clauses()))));
            } else {
                out.add(p);
            }
        }
        return out;
    }

    /**
     * The events of watch's JSON by log, in order, without the wall-clock time: the logs are followed side by side,
     * so one log's events and another's interleave as they come.
     */
    private static Map<String, List<String>> byLog(String out) throws Exception {
        Map<String, List<String>> logs = new TreeMap<>();
        for (String line : out.lines().toList()) {
            ObjectNode e = (ObjectNode) JSON.readTree(line);
            e.remove("wallTime");
            logs.computeIfAbsent(e.path("log").asText(), k -> new ArrayList<>()).add(e.toString());
        }
        return logs;
    }

    private static Cli watch(Path models) {
        return Cli.run("watch", "--no-follow", "--json", "--models", models.toString(), "--log",
                "sample-logs/depleted", "--log", "sample-logs/recharge", "--log", "sample-logs/direct");
    }

    /** Learning the same runs twice gives the same bytes, and format 2. */
    @Test
    void theSameTrainingRunsGiveTheSameBytes() throws Exception {
        Path first = tmp.resolve("first");
        Path second = tmp.resolve("second");
        for (Path dir : List.of(first, second)) {
            Cli r = Cli.run("learn", "--logs", "sample-logs", "--models", dir.toString());
            assertEquals(ExitCodes.OK, r.code(), r.err());
        }
        String text = Files.readString(first.resolve(ForecastFile.NAME));
        assertEquals(text, Files.readString(second.resolve(ForecastFile.NAME)));
        JsonNode file = JSON.readTree(text);
        assertEquals(ForecastModel.FORMAT, file.get("format").asInt());
        for (String key : List.of("limit", "threshold", "states", "obligations", "bounds", "events", "scorecards")) {
            assertFalse(file.has(key), "nothing property-specific at the top level: " + key);
        }
        assertEquals(List.of("battery", "charger-in-time", "no-abort", "navigation-in-time", "grasp-in-time"),
                names(file.get("properties")));
        assertNotEquals(Files.readString(FORMAT_1.resolve(ForecastFile.NAME)), text);
    }

    private static List<String> names(JsonNode n) {
        List<String> out = new ArrayList<>();
        n.fieldNames().forEachRemaining(out::add);
        return out;
    }
}
