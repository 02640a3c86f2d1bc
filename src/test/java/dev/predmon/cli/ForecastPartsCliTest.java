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
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code forecast.json}'s per-property parts are checked against the abstraction the models were learned with, as its
 * top-level fields are: {@code obligations} has an entry for every bounded response (an empty one when no training run
 * opened an obligation), {@code bounds} one for every bound but the safety property, and each entry fits its property.
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

    @Test
    void learnWritesAnEntryForEveryBoundedResponseEmptyWhenTrainingOpenedNone() throws IOException {
        ObjectNode o = (ObjectNode) forecast(Path.of("models")).get("obligations");
        assertEquals(List.of("charger-in-time", "grasp-in-time", "navigation-in-time"),
                iterable(o.fieldNames()), "the shipped abstraction's three bounded responses");
        assertEquals(0, o.get("grasp-in-time").get("discharged").size(), o.toString());
        assertEquals(0, o.get("grasp-in-time").get("censored").size(), o.toString());
        assertTrue(o.get("navigation-in-time").get("discharged").size() > 0, o.toString());
    }

    @Test
    void obligationsDeleted() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode f = forecast(models);
        f.remove("obligations");
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"), "'obligations' has no entry for "
                + "'charger-in-time', a bounded response of the abstraction the models were learned with");
    }

    /** The navigation deadline's entry alone: its warnings would be lost, and only they. */
    @Test
    void oneObligationDeleted() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode f = forecast(models);
        ((ObjectNode) f.get("obligations")).remove("navigation-in-time");
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"),
                "'obligations' has no entry for 'navigation-in-time'");
    }

    /** A navigation "discharged" after 500 ticks, against a deadline of 400: that would have been a violation. */
    @Test
    void aDurationLongerThanTheDeadline() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode f = forecast(models);
        ((ArrayNode) f.get("obligations").get("navigation-in-time").get("discharged")).add(500.0);
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"), "'obligations/navigation-in-time': an "
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
        ((ArrayNode) f.get("obligations").get("navigation-in-time").get("censored")).add(401.0);
        write(models, f);
        Cli accepted = Cli.run("classify", "--models", models.toString(), "--log", "sample-logs/direct/direct-1.log");
        assertEquals(ExitCodes.OK, accepted.code(), "let go at the tick past the deadline: " + accepted.err());
        ((ArrayNode) f.get("obligations").get("navigation-in-time").get("censored")).add(5000.0);
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"), "'obligations/navigation-in-time': an "
                + "obligation let go after 5000.0 ticks, more than one past the deadline of 400 ticks");
    }

    @Test
    void anObligationOfAPropertyThatIsNoBoundedResponse() throws IOException {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        ObjectNode f = forecast(models);
        ((ObjectNode) f.get("obligations")).set("no-abort", f.get("obligations").get("grasp-in-time").deepCopy());
        write(models, f);
        ModelFilesCliTest.refused(models, models.resolve("forecast.json"),
                "'obligations/no-abort': not a bounded response of the abstraction");
    }

    /**
     * Models with a reserve floor (40) and a ceiling (99.5) beside the battery, learned from the hand-written runs:
     * {@code bounds} holds both, and each change by hand is refused.
     */
    @Test
    void theBoundsPartIsCheckedEntryByEntry() throws Exception {
        Path abstraction = BoundForecastCliTest.abstraction(tmp);
        Path logs = tmp.resolve("logs");
        Path learned = tmp.resolve("learned");
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        Cli l = Cli.run("learn", "--logs", logs.toString(), "--models", learned.toString(), "--abstraction",
                abstraction.toString());
        assertEquals(ExitCodes.OK, l.code(), l.err());
        ObjectNode shipped = forecast(learned);
        assertEquals(List.of("full", "reserve"), iterable(shipped.get("bounds").fieldNames()));
        Path log = Files.writeString(tmp.resolve("run.log"), HandRuns.depleted().text());
        Cli judged = classify(learned, abstraction, log);
        assertTrue(judged.code() != ExitCodes.BAD_INPUT && judged.err().isEmpty(), "as learned, it judges: "
                + judged.err());

        ObjectNode f = shipped.deepCopy();
        f.remove("bounds");
        refused(learned, f, abstraction, log, "'bounds' has no entry for 'reserve', a bound with a floor or a ceiling "
                + "other than the safety property of the abstraction");
        f = shipped.deepCopy();
        ((ObjectNode) f.get("bounds")).remove("full");
        refused(learned, f, abstraction, log, "'bounds' has no entry for 'full'");
        f = shipped.deepCopy();
        ((ObjectNode) f.get("bounds").get("reserve")).put("limit", 999);
        refused(learned, f, abstraction, log, "'bounds/reserve': limit 999.0 is not the property's floor (40.0)");
        f = shipped.deepCopy();
        ((ObjectNode) f.get("bounds").get("reserve")).put("side", "ceiling");
        refused(learned, f, abstraction, log, "'bounds/reserve': side 'ceiling', but 'reserve' has no ceiling");
        f = shipped.deepCopy();
        ((ObjectNode) f.get("bounds").get("full")).put("side", "floor");
        refused(learned, f, abstraction, log, "'bounds/full': side 'floor', but 'full' has no floor");
        f = shipped.deepCopy();
        ((ObjectNode) f.get("bounds")).set("battery", f.get("bounds").get("reserve").deepCopy());
        refused(learned, f, abstraction, log, "'bounds/battery': not a bound with a floor or a ceiling other than the"
                + " safety property of the abstraction");
        f = shipped.deepCopy();
        ObjectNode states = (ObjectNode) f.get("bounds").get("reserve").get("states");
        states.set("ghost", states.get(states.fieldNames().next()).deepCopy());
        refused(learned, f, abstraction, log, "'bounds/reserve': machine 'ghost' is not one index.json lists");
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

    private static List<String> iterable(java.util.Iterator<String> names) {
        List<String> out = new java.util.ArrayList<>();
        names.forEachRemaining(out::add);
        return out;
    }
}
