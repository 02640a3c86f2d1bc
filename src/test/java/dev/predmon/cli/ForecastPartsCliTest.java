package dev.predmon.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code forecast.json}'s per-property entries are checked against the abstraction the models were learned with:
 * {@code properties} has an entry for every bounded response (an empty one when no training run opened an
 * obligation), one for every bound with a floor or a ceiling (the first floor among them), and each entry fits its
 * property, part by part.
 * A part deleted or changed by hand would silently drop or move a property's warnings (the navigation deadline's
 * warning lost, exit 6 instead of 1); each is now exit 3 and one line naming {@code forecast.json}.
 */
class ForecastPartsCliTest {

    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    @TempDir
    Path tmp;

    private ObjectNode forecast(Path models) throws IOException {
        return (ObjectNode) JSON.readTree(models.resolve("forecast.json").toFile());
    }

    private void write(Path models, ObjectNode forecast) throws IOException {
        Files.writeString(models.resolve("forecast.json"), JSON.writeValueAsString(forecast));
    }

    private static ObjectNode properties(ObjectNode forecast) {
        return (ObjectNode) forecast.get("properties");
    }

    @Test
    void learnWritesAnEntryForEveryBoundedResponseEmptyWhenTrainingOpenedNone() throws IOException {
        ObjectNode p = properties(forecast(Path.of("models")));
        List<String> deadlines = new ArrayList<>();
        p.fields().forEachRemaining(e -> {
            if (e.getValue().get("kind").asText().equals("deadline")) {
                deadlines.add(e.getKey());
            }
        });
        assertEquals(List.of("charger-in-time", "navigation-in-time", "grasp-in-time"), deadlines,
                "the shipped abstraction's three bounded responses, in its order");
        assertEquals(0, p.get("grasp-in-time").get("discharged").size(), p.toString());
        assertEquals(0, p.get("grasp-in-time").get("censored").size(), p.toString());
        assertTrue(p.get("navigation-in-time").get("discharged").size() > 0, p.toString());
    }

    @Test
    void everyDeadlineDeleted() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode f = forecast(models);
        properties(f).remove(List.of("charger-in-time", "navigation-in-time", "grasp-in-time"));
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"), "'properties' has no entry for "
                + "'charger-in-time', a bounded response of the abstraction the models were learned with");
    }

    /** The navigation deadline's entry alone: its warnings would be lost, and only they. */
    @Test
    void oneDeadlineDeleted() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode f = forecast(models);
        properties(f).remove("navigation-in-time");
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"),
                "'properties' has no entry for 'navigation-in-time'");
    }

    /** A navigation "discharged" after 500 ticks, against a deadline of 400: that would have been a violation. */
    @Test
    void aDurationLongerThanTheDeadline() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode f = forecast(models);
        ((ArrayNode) properties(f).get("navigation-in-time").get("discharged")).add(500.0);
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"), "'properties.navigation-in-time': an "
                + "obligation discharged after 500.0 ticks, past the deadline of 400 ticks");
    }

    /**
     * A navigation let go after 5,000 ticks: training lets go of one at the tick past its deadline (401) at the
     * latest. So long a "longest training obligation" would keep the deadline's novelty clause from ever warning.
     */
    @Test
    void aCensoredDurationFarPastTheDeadline() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode f = forecast(models);
        ((ArrayNode) properties(f).get("navigation-in-time").get("censored")).add(401.0);
        write(models, f);
        Cli accepted = Cli.run("classify", "--models", models.toString(), "--log", "sample-logs/direct/direct-1.log");
        assertEquals(ExitCodes.OK, accepted.code(), "let go at the tick past the deadline: " + accepted.err());
        ((ArrayNode) properties(f).get("navigation-in-time").get("censored")).add(5000.0);
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"), "'properties.navigation-in-time': an "
                + "obligation let go after 5000.0 ticks, more than one past the deadline of 400 ticks");
    }

    /** Each part of a deadline's entry is read where it is: a bad one is told at its path. */
    @Test
    void aDeadlinesRuleIsCheckedPartByPart() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode shipped = forecast(models);
        Path file = models.resolve("forecast.json");
        String[][] cases = {
                {"threshold", "1.5", "'properties.navigation-in-time.threshold': a threshold is a probability"},
                {"margin", "7", "'properties.navigation-in-time.margin': a margin is a share, from 0 to 1: 7.0"},
                {"validated", "\"yes\"", "'properties.navigation-in-time.validated': expected true or false"},
                {"rule", "\"elapsed\"", "'properties.navigation-in-time.rule': expected \"baseline\""},
                {"discharged", "3", "'properties.navigation-in-time.discharged': expected an array of numbers"},
                {"byInput", "[]", "'properties.navigation-in-time.byInput': expected an object"},
                {"kind", "\"survival\"", "'properties.navigation-in-time.kind': 'survival', expected one of bound, "
                        + "deadline, event"}};
        for (String[] c : cases) {
            ObjectNode f = shipped.deepCopy();
            ((ObjectNode) properties(f).get("navigation-in-time")).set(c[0], JSON.readTree(c[1]));
            write(models, f);
            ModelFilesCliTest.refused(models, file, c[2]);
        }
        ObjectNode f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("navigation-in-time")).remove("note");
        write(models, f);
        ModelFilesCliTest.refused(models, file, "'properties.navigation-in-time.note' is missing");
    }

    /**
     * The absence's event forecast (learned from the sample logs: 10 of their 30 runs abort) is checked as a bound's:
     * its parts, its states, its counts.
     */
    @Test
    void anEventsForecastIsCheckedPartByPart() throws IOException {
        Path models = tmp.resolve("learned");
        Cli l = Cli.run("learn", "--logs", "sample-logs", "--models", models.toString());
        assertEquals(ExitCodes.OK, l.code(), l.err());
        ObjectNode shipped = forecast(models);
        assertEquals("event", properties(shipped).get("no-abort").get("kind").asText());
        Path file = models.resolve("forecast.json");
        ObjectNode f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("no-abort")).put("threshold", 1.5);
        write(models, f);
        ModelFilesCliTest.refused(models, file, "'properties.no-abort.threshold': 1.5 is not a probability");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("no-abort")).put("limit", 20.0);
        write(models, f);
        ModelFilesCliTest.refused(models, file, "'properties.no-abort': limit 20.0 is not the indicator's floor (1.0)");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("no-abort")).put("violating", 30);
        write(models, f);
        ModelFilesCliTest.refused(models, file, "'properties.no-abort': a forecast from 30 violating of 30 runs");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("no-abort").get("calibration")).put("slope", -1);
        write(models, f);
        ModelFilesCliTest.refused(models, file, "'properties.no-abort.calibration.slope': expected a positive number");
        f = shipped.deepCopy();
        ObjectNode states = (ObjectNode) properties(f).get("no-abort").get("states");
        states.set("ghost", states.remove("direct"));
        write(models, f);
        ModelFilesCliTest.refused(models, file, "'properties.no-abort.states': machine 'ghost' is not one index.json "
                + "lists");
    }

    @Test
    void aDeadlineOfAPropertyThatIsNoBoundedResponse() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode f = forecast(models);
        properties(f).set("no-abort", properties(f).get("grasp-in-time").deepCopy());
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"),
                "'properties.no-abort': not a bounded response of the abstraction");
    }

    /** The first floor is a bound as any other, and the abstraction's: moved or changed, it is refused. */
    @Test
    void theFirstFloorIsTheAbstractions() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode shipped = forecast(models);
        Path file = models.resolve("forecast.json");
        ObjectNode f = shipped.deepCopy();
        properties(f).remove("battery");
        write(models, f);
        ModelFilesCliTest.refused(models, file, "'properties' has no entry for 'battery', the first floor of the "
                + "abstraction the models were learned with");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("battery")).put("side", "ceiling");
        write(models, f);
        ModelFilesCliTest.refused(models, file, "'properties' has no entry for 'battery', the first floor");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("battery")).put("limit", 19.0);
        write(models, f);
        ModelFilesCliTest.refused(models, file, "'properties.battery.limit': 19.0 is not the property's floor (20.0)");
    }

    /**
     * Models with a reserve floor (40) and a ceiling (99.5) beside the battery, learned from the hand-written runs:
     * {@code properties} holds both as bounds beside the battery's, and each change by hand is refused.
     */
    @Test
    void everyBoundIsCheckedEntryByEntry() throws Exception {
        Path abstraction = BoundForecastCliTest.abstraction(tmp);
        Path logs = tmp.resolve("logs");
        Path learned = tmp.resolve("learned");
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        Cli l = Cli.run("learn", "--logs", logs.toString(), "--models", learned.toString(), "--abstraction",
                abstraction.toString());
        assertEquals(ExitCodes.OK, l.code(), l.err());
        ObjectNode shipped = forecast(learned);
        for (String id : List.of("battery", "reserve", "full")) {
            assertEquals("bound", properties(shipped).get(id).get("kind").asText(), id);
        }
        Path log = Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text());
        Cli judged = classify(learned, abstraction, log);
        assertTrue(judged.code() != ExitCodes.BAD_INPUT && judged.err().isEmpty(), "as learned, it judges: "
                + judged.err());

        ObjectNode f = shipped.deepCopy();
        properties(f).remove("reserve");
        refused(learned, f, abstraction, log, "'properties' has no entry for 'reserve', a bound with a floor or a "
                + "ceiling other than the safety property of the abstraction");
        f = shipped.deepCopy();
        properties(f).remove("full");
        refused(learned, f, abstraction, log, "'properties' has no entry for 'full'");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("reserve")).put("limit", 999);
        refused(learned, f, abstraction, log, "'properties.reserve': limit 999.0 is not the property's floor (40.0)");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("reserve")).put("side", "ceiling");
        refused(learned, f, abstraction, log, "'properties.reserve': side 'ceiling', but 'reserve' has no ceiling");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("full")).put("side", "floor");
        refused(learned, f, abstraction, log, "'properties.full': side 'floor', but 'full' has no floor");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("reserve")).put("side", "up");
        refused(learned, f, abstraction, log, "'properties.reserve.side': side 'up': expected floor or ceiling");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("reserve")).remove("states");
        refused(learned, f, abstraction, log, "'properties.reserve.states' is missing");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("reserve")).remove("thresholdNote");
        refused(learned, f, abstraction, log, "'properties.reserve.thresholdNote' is missing");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("reserve")).put("rule", "never");
        refused(learned, f, abstraction, log, "'properties.reserve.rule': expected \"baseline\" or \"forecast\"");
        f = shipped.deepCopy();
        ((ObjectNode) properties(f).get("reserve")).put("safeLows", "low");
        refused(learned, f, abstraction, log, "'properties.reserve.safeLows': expected an array of numbers");
        f = shipped.deepCopy();
        ObjectNode states = (ObjectNode) properties(f).get("reserve").get("states");
        states.set("ghost", states.get(states.fieldNames().next()).deepCopy());
        refused(learned, f, abstraction, log, "'properties.reserve.states': machine 'ghost' is not one index.json "
                + "lists");
        f = shipped.deepCopy();
        ObjectNode state = (ObjectNode) properties(f).get("reserve").get("states").elements().next().elements().next();
        state.put("violated", state.get("runs").asInt() + 1);
        refused(learned, f, abstraction, log, "counts out of range");
    }

    private static Cli classify(Path models, Path abstraction, Path log) {
        return Cli.run("classify", "--models", models.toString(), "--abstraction", abstraction.toString(), "--log",
                log.toString());
    }

    /** {@code models} with {@code forecast} as its forecast are refused with one line naming it and saying {@code what}. */
    private void refused(Path models, ObjectNode forecast, Path abstraction, Path log, String what) throws IOException {
        Path file = models.resolve("forecast.json");
        String before = Files.readString(file);
        write(models, forecast);
        try {
            Cli r = classify(models, abstraction, log);
            assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
            List<String> lines = r.err().strip().lines().toList();
            assertEquals(1, lines.size(), r.err());
            assertTrue(lines.get(0).startsWith("predmon: " + file + ": ") && lines.get(0).contains(what), r.err());
            assertEquals("", r.out(), "no verdict");
        } finally {
            Files.writeString(file, before);
        }
    }
}
