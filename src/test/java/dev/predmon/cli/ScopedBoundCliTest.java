package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.monitor.WarningRule;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.Traces;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A bound with a scope: the battery at least 48% on the way to the kitchen (from a {@code goTo kitchen} to the next
 * {@code goTo charging_station}). Every recharge and depleted run goes below 48 on its way to the charger, out of
 * that scope; only some of them on the way to the kitchen. Its value forecast is learned from the runs as the checker judged them, and {@code watch} forecasts,
 * warns and holds it violated only while the scope is open.
 */
class ScopedBoundCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String ID = "kitchen-reserve";

    @TempDir
    Path tmp;

    /** The thesis's abstraction with the scoped floor, as a file in {@code tmp}. */
    private Path abstraction() throws Exception {
        Cli shown = Cli.run("abstraction", "show", "thesis");
        assertEquals(0, shown.code(), shown.err());
        ObjectNode a = (ObjectNode) JSON.readTree(shown.out());
        a.put("name", "thesis-kitchen-reserve");
        ArrayNode properties = (ArrayNode) a.get("properties");
        ObjectNode p = properties.addObject();
        p.put("id", ID).put("name", "battery >= 48% on the way to the kitchen").put("kind", "bound")
                .put("action", "turn back to the charger").put("floor", 48.0)
                .set("value", properties.get(0).get("value").deepCopy());
        ObjectNode scope = p.putObject("scope");
        scope.putObject("from").put("kind", "command").put("protocol", "GoTo").put("command", "goTo")
                .put("argument", "kitchen");
        scope.putObject("until").put("kind", "command").put("protocol", "GoTo").put("command", "goTo")
                .put("argument", "charging_station");
        Path file = tmp.resolve("kitchen-reserve.json");
        Files.writeString(file, a.toPrettyString());
        return file;
    }

    /** A console capture, record by record, with each record's first line remembered by name. */
    private static final class Capture {
        private final StringBuilder text = new StringBuilder(
                "Detected ABI qt5_12-x86_64, using ABI qt5_12-x86_64.\n"
                        + "[\u001b[01;34mINFO\u001b[00m] |yarp.os.Port| Port /monitor active at tcp://192.168.1.10:10031/\n");
        private long lines = 2;
        private int ticks;

        /** Adds a record; returns its first line. */
        long record(String kind, String from, String to, String protocol, String command, String arguments,
                    String reply) {
            long line = lines + 1;
            text.append("[\u001b[01;32mDEBUG\u001b[00m] ").append(kind).append(" intercepted:\n")
                    .append("  From      : ").append(from).append('\n')
                    .append("  To        : ").append(to).append('\n')
                    .append("  Protocol  : ").append(protocol).append('\n')
                    .append("  Command   : ").append(command).append('\n')
                    .append("  Arguments : ").append(arguments).append('\n')
                    .append("  Reply     : ").append(reply).append('\n');
            lines += 7;
            return line;
        }

        void tick() {
            record("Tick", "/tick/monitor", "/monitor", "Tick", "", Integer.toString(++ticks), "");
        }

        /** A tick and the battery's level; returns the level reply's line. */
        long level(double level) {
            tick();
            record("Command", "/BatteryReaderBatteryLevelClient", "/BatteryComponent", "BatteryReader", "level", "",
                    "");
            return record("Reply", "/BatteryComponent", "/BatteryReaderBatteryLevelClient", "BatteryReader", "level",
                    "", Double.toString(level));
        }

        /** A goTo to {@code where} and its reply; returns the command's line. */
        long goTo(String where) {
            tick();
            long line = record("Command", "/GoToGoToClient/" + where, "/GoToComponent", "GoTo", "goTo", where, "");
            record("Reply", "/GoToComponent", "/GoToGoToClient/" + where, "GoTo", "goTo", "", where);
            return line;
        }
    }

    private static List<JsonNode> of(List<JsonNode> events, String property) {
        return events.stream().filter(e -> e.path("property").asText().equals(property)).toList();
    }

    @Test
    void aScopedFloorIsLearnedForecastWarnedAndViolatedOnlyInItsScope() throws Exception {
        Path abstraction = abstraction();
        Path logs = BoundForecastCliTest.trainingLogs(tmp);

        // learned from the runs as the checker judged them: recharge runs dip below 40 out of the scope
        Abstraction a = AbstractionFiles.load(abstraction);
        List<LogTrace.Run> runs = Traces.readAll(ScenarioLayout.scan(logs, a).stream()
                .flatMap(s -> s.logs().stream()).toList(), a).values().stream().flatMap(t -> t.runs().stream())
                .toList();
        long scoped = runs.stream().filter(r -> r.timing().violated(ID)).count();
        // the battery's readings, the same value, read in every run's every record
        long raw = runs.stream().filter(r -> r.timing().readings().stream().anyMatch(x -> x.value() < 48)).count();
        assertTrue(scoped > 0 && scoped < raw, "scoped " + scoped + ", below 48 anywhere " + raw);
        Path models = tmp.resolve("models");
        Cli learn = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString(), "--abstraction",
                abstraction.toString());
        assertEquals(0, learn.code(), learn.err());
        JsonNode forecast = JSON.readTree(models.resolve("forecast.json").toFile()).get("properties").get(ID);
        assertEquals(scoped, forecast.get("violating").asLong(), "labelled by the scoped verdict: " + forecast);
        assertFalse(forecast.get("safeLows").isEmpty(), forecast.toString());
        forecast.get("safeLows").forEach(low -> assertTrue(low.asDouble() >= 48,
                "a safe run's lowest value is the lowest within the scope: " + forecast.get("safeLows")));

        // below the floor out of the scope, back up, then below it on the way to the kitchen
        Capture c = new Capture();
        for (double level : new double[] {60, 50, 45, 44, 55}) {
            c.level(level);
        }
        long opens = c.goTo("kitchen");
        for (double level : new double[] {54, 52, 50, 49}) {
            c.level(level);
        }
        long violatedAt = c.level(47);
        c.level(46);
        long closes = c.goTo("charging_station");
        c.level(45);
        c.level(44);
        Path trace = tmp.resolve("scoped.txt");
        Files.writeString(trace, c.text.toString());

        Cli watched = Cli.run("watch", "--log", trace.toString(), "--models", models.toString(), "--no-follow",
                "--json");
        List<JsonNode> events = new ArrayList<>();
        for (String line : watched.out().lines().toList()) {
            events.add(JSON.readTree(line));
        }
        List<JsonNode> own = of(events, ID);
        assertTrue(own.stream().noneMatch(e -> e.get("line").asLong() < opens),
                "nothing of it before its scope opens, though the value went below 48 and back: " + own);
        assertTrue(own.stream().noneMatch(e -> e.get("line").asLong() > closes),
                "nothing of it once its scope closed, though the value is below 48: " + own);
        List<JsonNode> violations = own.stream().filter(e -> e.get("event").asText().equals("violation")).toList();
        assertEquals(1, violations.size(), watched.out());
        assertEquals(violatedAt, violations.get(0).get("line").asLong());
        assertEquals(47.0, violations.get(0).get("value").asDouble());
        assertTrue(own.stream().anyMatch(e -> e.get("event").asText().equals("forecast")
                && e.get("line").asLong() < violatedAt), "forecast in its scope: " + own);
        assertTrue(own.stream().filter(e -> e.get("event").asText().equals("warning"))
                .allMatch(e -> e.get("line").asLong() < violatedAt), "a warning only ahead of it: " + own);
        List<JsonNode> recovered = own.stream().filter(e -> e.get("event").asText().equals("recovered")).toList();
        assertEquals(1, recovered.size(), own.toString());
        assertEquals("scope", recovered.get(0).get("cause").asText());
        assertEquals(closes, recovered.get(0).get("line").asLong());
        assertTrue(recovered.get(0).get("reason").asText().startsWith(
                "'battery >= 48% on the way to the kitchen' (kitchen-reserve): out of its scope at "),
                recovered.get(0).toString());
        boolean warned = own.stream().anyMatch(e -> e.get("event").asText().equals("warning"));
        assertEquals(warned ? 1 : 6, watched.code(), "its violation decides the exit code: " + watched.err());
        JsonNode end = events.get(events.size() - 1);
        assertEquals("end", end.get("event").asText());
        JsonNode status = end.get("properties").get(end.get("properties").size() - 1);
        assertEquals(ID, status.get("property").asText());
        assertEquals("violated", status.get("verdict").asText(), "the run's verdict stays: " + status);
        assertFalse(of(events, "battery").stream().anyMatch(e -> e.get("event").asText().equals("violation")),
                "the battery's floor of 20 held");

        // whatever the rule (the thesis's match rule too), the violation ends where the scope closes
        for (WarningRule rule : WarningRule.values()) {
            Cli ruled = Cli.run("watch", "--log", trace.toString(), "--models", models.toString(), "--no-follow",
                    "--json", "--rule", rule.name().toLowerCase(java.util.Locale.ROOT));
            List<JsonNode> seen = new ArrayList<>();
            for (String line : ruled.out().lines().toList()) {
                seen.add(JSON.readTree(line));
            }
            List<JsonNode> ends = of(seen, ID).stream().filter(e -> e.get("event").asText().equals("recovered"))
                    .toList();
            assertEquals(1, ends.size(), rule + ": " + ruled.out() + ruled.err());
            assertEquals("scope", ends.get(0).get("cause").asText(), rule.toString());
            assertEquals(closes, ends.get(0).get("line").asLong(), rule.toString());
            assertEquals(violatedAt, of(seen, ID).stream().filter(e -> e.get("event").asText().equals("violation"))
                    .findFirst().orElseThrow().get("line").asLong(), rule + ": the violation it ends");
        }
    }
}
