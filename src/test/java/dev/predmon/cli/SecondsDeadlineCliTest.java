package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.parse.LogRecord;
import dev.predmon.support.HandRuns;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A bounded response whose deadline counts seconds ({@code "within": {"seconds": T}}), the navigation's here: a
 * deadline that passes while the robot is frozen is violated at the first record after it, also when the silence is
 * long enough to begin a new run; and in a console capture without time stamps, T seconds are T seconds of ticks of
 * the length {@code --tick-seconds} gives.
 */
class SecondsDeadlineCliTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path tmp;

    /** The thesis's abstraction with the navigation's deadline in seconds, as a file. */
    private Path abstraction(int seconds) throws Exception {
        Cli shown = Cli.run("abstraction", "show", "thesis");
        assertEquals(0, shown.code(), shown.err());
        ObjectNode a = (ObjectNode) JSON.readTree(shown.out());
        a.put("name", "thesis-seconds");
        boolean found = false;
        for (JsonNode p : a.get("properties")) {
            if (p.get("id").asText().equals("navigation-in-time")) {
                ((ObjectNode) p).put("name", "a navigation ends within " + seconds + " seconds");
                ((ObjectNode) p).putObject("within").put("seconds", seconds);
                found = true;
            }
        }
        assertTrue(found, a.toString());
        return Files.writeString(tmp.resolve("seconds.json"), a.toPrettyString());
    }

    /** Models of the hand-written runs, learned with {@code abstraction}. */
    private Path models(Path abstraction) throws Exception {
        Path logs = tmp.resolve("logs");
        Path models = tmp.resolve("models");
        CliEndToEndTest.scenario(logs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(logs, "depleted", true, HandRuns.depleted().text());
        Cli r = Cli.run("learn", "--logs", logs.toString(), "--models", models.toString(), "--abstraction",
                abstraction.toString());
        assertEquals(ExitCodes.OK, r.code(), r.err());
        return models;
    }

    /**
     * A navigation to the kitchen from t=0, still running at t=20, then a delay of 40 s: frozen ({@code split} false),
     * nothing logged until t=60; or ({@code split}) the same delay as 20 s + 20 s, a status at t=40. At t=60 it
     * arrives, 60 s after its goTo, past the deadline of 45 s.
     */
    private static Records navigation(boolean split) {
        Records r = new Records().at(0).level(80).charging(false).isAt("kitchen", false).goTo("kitchen")
                .status("kitchen", 1).at(10).status("kitchen", 1).level(79).at(20).status("kitchen", 1).level(78);
        if (split) {
            r.at(40).status("kitchen", 1).level(78);
        }
        return r.at(60).status("kitchen", 2).level(77);
    }

    /**
     * The robot freezes for 40 s in the middle of a navigation whose deadline is 45 s: the silence begins a new run
     * (30 s), and the deadline that passed in it is violated at the first record after it, in the run it belongs to:
     * the violation event, the hook, exit 6. The same delay as 20 s + 20 s, which begins no run, gives the same.
     */
    @Test
    @Timeout(120)
    void aDeadlinePassedWhileTheRobotWasFrozenIsViolatedNotDropped() throws Exception {
        Path models = models(abstraction(45));
        for (boolean split : new boolean[] {false, true}) {
            Records run = navigation(split);
            long arrival = run.list().stream().filter(r -> r.time() >= 60).mapToLong(LogRecord::line).min()
                    .orElseThrow();
            Path log = Files.writeString(tmp.resolve("robot-" + split + ".log"), "");
            Path heard = tmp.resolve("heard-" + split);
            Cli.Running w = Cli.start("watch", "--log", log.toString(), "--models", models.toString(), "--abstraction",
                    tmp.resolve("seconds.json").toString(), "--json", "--on-violation",
                    "echo \"$PREDMON_PROPERTY $PREDMON_RUN\" >> '" + heard + "'");
            FleetWatchTest.await(() -> w.err().toString().contains("following " + log), "follows: " + w.err());
            Files.writeString(log, run.text(), StandardOpenOption.APPEND);
            FleetWatchTest.await(() -> Files.exists(heard) && readable(heard).contains("navigation-in-time"),
                    "the hook hears the violation: " + w.out() + w.err());
            w.stop();
            JsonNode violation = new Cli(0, w.out().toString(), "").jsonLines().stream()
                    .filter(e -> e.get("event").asText().equals("violation")
                            && e.get("property").asText().equals("navigation-in-time")).findFirst().orElseThrow();
            assertEquals(arrival, violation.get("line").asLong(), "at the first record past the deadline: " + violation);
            assertEquals(0, violation.get("run").asInt(), "in the navigation's run: " + violation);
            assertEquals(List.of("navigation-in-time 0"), Files.readAllLines(heard));
            assertEquals(ExitCodes.UNWARNED_VIOLATION, w.code().get(), split + ": " + w.out() + w.err());
            long runs = new Cli(0, w.out().toString(), "").jsonLines().stream()
                    .filter(e -> e.get("event").asText().equals("run")).count();
            assertEquals(split ? 0 : 1, runs, "the 40 s silence begins a run, 20 s do not: " + w.out());
        }
    }

    private static String readable(Path p) {
        try {
            return Files.readString(p);
        } catch (java.io.IOException e) {
            return "";
        }
    }

    /** One record of a console capture: the monitor's console output, without time stamps. */
    private static String record(String kind, String from, String to, String protocol, String command, String args,
                                 String reply) {
        return String.format(Locale.ROOT, "[DEBUG] %s intercepted:%n  From      : %s%n  To        : %s%n"
                + "  Protocol  : %s%n  Command   : %s%n  Arguments : %s%n  Reply     : %s%n", kind, from, to, protocol,
                command, args, reply);
    }

    /** A console capture of 50 ticks: a goTo at tick 2, its arrival at tick 43, 41 ticks later. */
    private static String consoleNavigation() {
        StringBuilder b = new StringBuilder();
        for (int t = 1; t <= 50; t++) {
            b.append(record("Tick", "/tick/monitor", "/monitor", "Tick", "", Integer.toString(t), ""));
            b.append(record("Command", "/BatteryReaderBatteryLevelClient", "/BatteryComponent", "BatteryReader",
                    "level", "", ""));
            b.append(record("Reply", "/BatteryComponent", "/BatteryReaderBatteryLevelClient", "BatteryReader", "level",
                    "", "90.0"));
            if (t == 2) {
                b.append(record("Command", "/GoToGoToClient/kitchen", "/GoToComponent", "GoTo", "goTo", "kitchen", ""));
                b.append(record("Reply", "/GoToComponent", "/GoToGoToClient/kitchen", "GoTo", "goTo", "kitchen", ""));
            }
            if (t == 43) {
                b.append(record("Command", "/GoToGoToClient/kitchen", "/GoToComponent", "GoTo", "getStatus", "kitchen",
                        ""));
                b.append(record("Reply", "/GoToComponent", "/GoToGoToClient/kitchen", "GoTo", "getStatus", "kitchen",
                        "2"));
            }
        }
        return b.toString();
    }

    /** The line of the {@code Tick} record of tick {@code n} in {@link #consoleNavigation()}: 3 records a tick, 5 at 2. */
    private static long tickLine(int n) {
        long records = 3L * (n - 1) + (n > 2 ? 2 : 0);
        return records * 7 + 1;
    }

    /**
     * {@code "within": {"seconds": 30}} in a console capture. With ticks of 0.5 s, 30 s are 60 ticks: the navigation
     * that arrived 41 ticks (20.5 s) after its goTo was in time. With ticks of 2 s, 30 s are 15 ticks: the goTo at
     * tick 2 (t=4 s) is due by tick 17 (t=34 s), and the record of tick 18 (t=36 s) violates it.
     */
    @Test
    void aDeadlineInSecondsCountsTicksOfTheGivenLength() throws Exception {
        Path abstraction = abstraction(30);
        Path models = models(abstraction);
        Path log = Files.writeString(tmp.resolve("console.txt"), consoleNavigation());

        List<JsonNode> half = watch(models, abstraction, log, "0.5");
        assertTrue(half.stream().noneMatch(e -> e.get("event").asText().equals("violation")
                && e.get("property").asText().equals("navigation-in-time")), half.toString());
        assertEquals("holds", verdict(half, "navigation-in-time").get("verdict").asText(), half.toString());

        List<JsonNode> two = watch(models, abstraction, log, "2");
        JsonNode v = two.stream().filter(e -> e.get("event").asText().equals("violation")
                && e.get("property").asText().equals("navigation-in-time")).findFirst().orElseThrow();
        assertEquals(tickLine(18), v.get("line").asLong(), v.toString());
        assertEquals(36.0, v.get("time").asDouble(), v.toString());
    }

    private static List<JsonNode> watch(Path models, Path abstraction, Path log, String tickSeconds) throws Exception {
        Cli r = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--abstraction",
                abstraction.toString(), "--no-follow", "--json", "--tick-seconds", tickSeconds);
        assertTrue(r.code() != ExitCodes.BAD_INPUT, r.err());
        return r.jsonLines();
    }

    /** The end summary's verdict of {@code property}. */
    private static JsonNode verdict(List<JsonNode> events, String property) {
        JsonNode end = Cli.firstEvent(events, "end").orElseThrow();
        for (JsonNode p : end.get("properties")) {
            if (p.get("property").asText().equals(property)) {
                return p;
            }
        }
        throw new AssertionError(property + " not in " + end);
    }
}
