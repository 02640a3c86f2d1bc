package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A fleet in one process: {@code watch} with several logs (named, a directory, a glob) gives each log its own
 * monitor, tags every event with its log, and exits 1 when any log warned.
 */
class FleetWatchTest {

    private static final Path MODELS = Path.of("models");

    @TempDir
    Path dir;

    static String run(Scenario s, long seed) {
        return LogWriter.toText(Simulator.run(s, seed, SimOptions.defaults()), SimOptions.defaults());
    }

    private static List<JsonNode> events(String out) throws Exception {
        return new Cli(0, out, "").jsonLines();
    }

    private static List<JsonNode> of(List<JsonNode> events, String log, String kind) {
        return events.stream().filter(e -> e.get("log").asText().equals(log) && e.get("event").asText().equals(kind))
                .toList();
    }

    @Test
    void eachLogHasItsOwnMonitorAndEveryEventNamesItsLog() throws Exception {
        Path faulty = Files.writeString(dir.resolve("robot-1.log"), run(Scenario.DEPLETED, 9001));
        Path nominal = Files.writeString(dir.resolve("robot-2.log"), run(Scenario.RECHARGE, 9002));
        Cli w = Cli.run("watch", "--log", faulty.toString(), "--log", nominal.toString(), "--models", MODELS.toString(),
                "--no-follow", "--json");
        assertEquals(ExitCodes.WARNING, w.code(), "one log warned: " + w.err());
        List<JsonNode> events = events(w.out());
        assertTrue(events.stream().allMatch(e -> e.has("log")), w.out());
        List<String> keys = new ArrayList<>();
        events.get(0).fieldNames().forEachRemaining(keys::add);
        assertEquals(List.of("event", "log"), keys.subList(0, 2), "\"event\" stays first, \"log\" follows it");
        assertEquals(List.of("battery", "no-abort"), of(events, faulty.toString(), "warning").stream()
                .map(v -> v.get("property").asText()).toList(), "warned of both before each violation");
        assertEquals(List.of("battery", "no-abort"), of(events, faulty.toString(), "violation").stream()
                .map(v -> v.get("property").asText()).toList(), "the depleted run's navigation aborts when it runs dry");
        assertEquals(0, of(events, nominal.toString(), "warning").size(), "the nominal run raises no warning");
        assertFalse(of(events, nominal.toString(), "eliminated").isEmpty(), "its own models are eliminated too");
        JsonNode faultyEnd = of(events, faulty.toString(), "end").get(0);
        JsonNode nominalEnd = of(events, nominal.toString(), "end").get(0);
        assertTrue(faultyEnd.get("warning").asBoolean() && faultyEnd.get("lead").asDouble() > 0, faultyEnd.toString());
        assertFalse(nominalEnd.get("warning").asBoolean() || nominalEnd.get("violation").asBoolean(), nominalEnd.toString());
        // The same logs watched one at a time give the same warnings: the logs do not influence each other.
        Cli alone = Cli.run("watch", "--log", faulty.toString(), "--models", MODELS.toString(), "--no-follow", "--json");
        List<JsonNode> warningsAlone = events(alone.out()).stream()
                .filter(e -> e.get("event").asText().equals("warning")).toList();
        assertFalse(warningsAlone.get(0).has("log"), "one log named: events as before");
        List<JsonNode> warnings = of(events, faulty.toString(), "warning");
        assertEquals(warningsAlone.stream().map(e -> e.get("line") + " " + e.get("time")).toList(),
                warnings.stream().map(e -> e.get("line") + " " + e.get("time")).toList());
    }

    @Test
    void textLinesArePrefixedWithTheirLogAndOnlyNominalRunsExit0() throws Exception {
        Path a = Files.writeString(dir.resolve("a.log"), run(Scenario.RECHARGE, 9002));
        Path b = Files.writeString(dir.resolve("b.log"), run(Scenario.DIRECT, 9003));
        Cli w = Cli.run("watch", "--log", a.toString(), "--log", b.toString(), "--models", MODELS.toString(),
                "--no-follow", "--eliminations");
        assertEquals(ExitCodes.OK, w.code(), w.err());
        assertTrue(w.out().lines().anyMatch(l -> l.startsWith(a + ": t=") && l.contains("eliminated")), w.out());
        assertTrue(w.out().lines().anyMatch(l -> l.startsWith(b + ": t=") && l.contains("eliminated")), w.out());
        assertTrue(w.out().contains("end of " + a + ":") && w.out().contains("end of " + b + ":"), w.out());
    }

    @Test
    void aGlobMatchesItsFilesOnlyAndADirectoryItsLogs() throws Exception {
        Path robots = Files.createDirectories(dir.resolve("robots"));
        Files.writeString(robots.resolve("robot-1.log"), run(Scenario.DEPLETED, 9001));
        Files.writeString(robots.resolve("robot-2.log"), run(Scenario.RECHARGE, 9002));
        Files.writeString(robots.resolve("robot-2.log.truth.json"), "{}");
        Files.writeString(robots.resolve("other.txt"), run(Scenario.DIRECT, 9003));
        Cli glob = Cli.run("watch", "--log", robots.resolve("robot-*.log").toString(), "--models", MODELS.toString(),
                "--no-follow", "--json");
        assertEquals(ExitCodes.WARNING, glob.code(), glob.err());
        assertEquals(List.of(robots.resolve("robot-1.log").toString(), robots.resolve("robot-2.log").toString()),
                events(glob.out()).stream().filter(e -> e.get("event").asText().equals("end"))
                        .map(e -> e.get("log").asText()).toList());
        Cli all = Cli.run("watch", "--log", robots.toString(), "--models", MODELS.toString(), "--no-follow", "--json");
        assertEquals(List.of("other.txt", "robot-1.log", "robot-2.log"),
                events(all.out()).stream().filter(e -> e.get("event").asText().equals("end"))
                        .map(e -> Path.of(e.get("log").asText()).getFileName().toString()).toList());
    }

    @Test
    void withNoFollowAGlobOrDirectoryWithoutLogsIsBadInput() throws Exception {
        Path empty = Files.createDirectories(dir.resolve("empty"));
        Cli d = Cli.run("watch", "--log", empty.toString(), "--models", MODELS.toString(), "--no-follow");
        assertEquals(ExitCodes.BAD_INPUT, d.code());
        assertTrue(d.err().contains(empty + ": is a directory with no log file"), d.err());
        Cli g = Cli.run("watch", "--log", empty.resolve("*.log").toString(), "--models", MODELS.toString(), "--no-follow");
        assertEquals(ExitCodes.BAD_INPUT, g.code());
        assertTrue(g.err().contains("*.log: no file matches"), g.err());
    }

    /** A robot that starts later adds its log to the directory: it is picked up and warned on, live. */
    @Test
    @Timeout(60)
    void aLogThatAppearsInAWatchedDirectoryIsFollowed() throws Exception {
        newLogFollowed();
    }

    /** The same, with the file-change notification set aside: every log is polled, new ones looked for each second. */
    @Test
    @Timeout(60)
    void withPollingForcedALogThatAppearsIsFollowedToo() throws Exception {
        newLogFollowed("--polling");
    }

    private void newLogFollowed(String... options) throws Exception {
        Path robots = Files.createDirectories(dir.resolve("fleet"));
        List<String> args = new ArrayList<>(List.of("watch", "--log", robots.toString(), "--models", MODELS.toString(),
                "--json"));
        args.addAll(List.of(options));
        Cli.Running watch = Cli.start(args.toArray(String[]::new));
        StringWriter out = watch.out();
        StringWriter err = watch.err();
        await(() -> err.toString().contains("waiting for logs in " + robots), "announces that it waits");
        Path quiet = Files.writeString(robots.resolve("robot-2.log"), run(Scenario.RECHARGE, 9002));
        Path late = robots.resolve("robot-7.log");
        Files.writeString(late, run(Scenario.DEPLETED, 9001));
        await(() -> out.toString().contains("\"event\":\"warning\",\"log\":\"" + late + "\""), "warns on the new log");
        await(() -> out.toString().contains("\"log\":\"" + quiet + "\""), "follows the other one");
        watch.stop();
        assertEquals(ExitCodes.WARNING, watch.code().get(), err.toString());
        assertFalse(out.toString().contains("\"event\":\"warning\",\"log\":\"" + quiet + "\""), out.toString());
    }

    static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long deadline = System.nanoTime() + 20_000_000_000L;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out: " + what);
            }
            Thread.sleep(10);
        }
    }
}
