package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.sun.net.httpserver.HttpServer;
import dev.predmon.simulate.Day;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.File;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * {@code watch --on-warning/--on-violation}: the warning reaches the robot, and the README's two recipes (a YARP
 * port through {@code yarp write}, an HTTP endpoint through {@code curl}) work as written.
 */
class WatchHooksTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path MODELS = Path.of("models");

    @TempDir
    Path dir;

    private Path log;

    @BeforeEach
    void depletedRun() throws Exception {
        assumeTrue(Files.isExecutable(Path.of("/bin/sh")), "hook commands run with /bin/sh, which this system lacks");
        log = Files.writeString(dir.resolve("robot-1.log"), FleetWatchTest.run(Scenario.DEPLETED, 9001));
    }

    /** The events of {@code kind} that {@code watch --json} printed, in order. */
    private static List<JsonNode> events(Cli w, String kind) throws Exception {
        List<JsonNode> found = new ArrayList<>();
        for (String line : w.out().strip().split("\n", -1)) {
            JsonNode e = JSON.readTree(line);
            if (e.get("event").asText().equals(kind)) {
                found.add(e);
            }
        }
        return found;
    }

    @Test
    void eachWarningAndViolationRunsItsCommandOnceWithTheEventOnStdin() throws Exception {
        Path warnings = dir.resolve("warnings");
        Path violations = dir.resolve("violations");
        Cli w = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow", "--json",
                "--on-warning", "echo this-goes-nowhere; cat >> '" + warnings + "'",
                "--on-violation", "cat >> '" + violations + "'");
        assertEquals(ExitCodes.WARNING, w.code(), w.err());
        // the depleted run is warned of its battery, then of the navigation that aborts when the battery is empty
        assertEquals(List.of("battery", "no-abort"), properties(events(w, "warning")), w.out());
        assertEquals(events(w, "warning"), heard(warnings), "each warning once, the same object --json prints");
        assertEquals(List.of("battery", "no-abort"), properties(events(w, "violation")), w.out());
        assertEquals(events(w, "violation"), heard(violations), "each violation once");
        assertTrue(!w.out().contains("this-goes-nowhere"), "a hook's stdout does not mix with --json: " + w.out());
    }

    /** What a hook read on its stdin, one event a call, each naming the log, which {@code --json} does not. */
    private List<JsonNode> heard(Path file) throws Exception {
        List<JsonNode> got = new ArrayList<>();
        for (String line : Files.readAllLines(file)) {
            JsonNode e = JSON.readTree(line);
            assertEquals(log.toString(), e.get("log").asText(), "the hook always hears which log");
            ((ObjectNode) e).remove("log");
            got.add(e);
        }
        return got;
    }

    private static List<String> properties(List<JsonNode> events) {
        return events.stream().map(e -> e.get("property").asText()).toList();
    }

    @Test
    void aFailingHookIsReportedAndWatchCarriesOn() throws Exception {
        Cli w = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow",
                "--on-warning", "exit 7");
        assertEquals(ExitCodes.WARNING, w.code(), "the monitor's own exit code: " + w.err());
        assertTrue(w.out().contains("VIOLATION"), "events after the failed hook are still printed: " + w.out());
        assertTrue(w.err().contains("predmon: --on-warning: warning of " + log + " line "), w.err());
        assertTrue(w.err().contains(": failed with exit code 7"), w.err());
    }

    @Test
    void aTimeoutThatIsNotPositiveIsAUsageError() {
        Cli w = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow",
                "--on-warning", "true", "--hook-timeout", "0");
        assertEquals(ExitCodes.USAGE, w.code(), w.err());
        assertTrue(w.err().contains("--hook-timeout"), w.err());
    }

    /** The README's curl recipe, against an HTTP endpoint on loopback. */
    @Test
    void curlRecipePostsTheWarningToAnHttpEndpoint() throws Exception {
        assumeTrue(onPath("curl"), "curl is not installed: the curl recipe cannot be tried");
        BlockingQueue<String> bodies = new ArrayBlockingQueue<>(10);
        HttpServer server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0);
        server.createContext("/predmon/warning", x -> {
            bodies.add(x.getRequestMethod() + " " + x.getRequestHeaders().getFirst("Content-Type") + " "
                    + new String(x.getRequestBody().readAllBytes(), StandardCharsets.UTF_8).strip());
            x.sendResponseHeaders(204, -1);
            x.close();
        });
        server.start();
        try {
            String url = "http://127.0.0.1:" + server.getAddress().getPort() + "/predmon/warning";
            Cli w = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow",
                    "--on-warning", "curl -sS --fail --max-time 5 -H 'Content-Type: application/json' "
                            + "--data-binary @- " + url);
            assertEquals(ExitCodes.WARNING, w.code(), w.err());
            String body = bodies.poll(10, TimeUnit.SECONDS);
            assertNotNull(body, "the endpoint got nothing: " + w.err());
            assertTrue(body.startsWith("POST application/json {\"event\":\"warning\",\"log\":"), body);
            assertTrue(!w.err().contains("--on-warning"), "the post succeeded: " + w.err());
        } finally {
            server.stop(0);
        }
    }

    /**
     * The YARP recipe of docs/watch.md, with a stand-in for {@code yarp} (YARP is not installed here) that records
     * what it was asked to write: the bottles a YARP reader on the robot gets, from the environment variables, one a
     * warning. A property without a value (no-abort) leaves its place empty.
     */
    @Test
    void yarpRecipeWritesOneBottleWithTheWarningsFields() throws Exception {
        Path bin = Files.createDirectories(dir.resolve("bin"));
        Path yarp = Files.writeString(bin.resolve("yarp"), "#!/bin/sh\necho \"$@\" >> '" + dir.resolve("args")
                + "'\ncat >> '" + dir.resolve("bottles") + "'\n");
        Files.setPosixFilePermissions(yarp, PosixFilePermissions.fromString("rwxr-xr-x"));
        String recipe = "echo \"warning $PREDMON_PROPERTY $PREDMON_VALUE $PREDMON_TIME\" | yarp write ... /robot/predmon:i";
        Cli w = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow", "--json",
                "--on-warning", "PATH='" + bin + "':$PATH; " + recipe);
        List<JsonNode> warnings = events(w, "warning");
        assertEquals(List.of("write ... /robot/predmon:i", "write ... /robot/predmon:i"),
                Files.readAllLines(dir.resolve("args")));
        JsonNode battery = warnings.get(0);
        assertEquals(List.of("warning battery " + String.format(Locale.ROOT, "%.2f", battery.get("value").asDouble())
                        + " " + battery.get("time").asDouble(),
                "warning no-abort  " + warnings.get(1).get("time").asDouble()),
                Files.readAllLines(dir.resolve("bottles")));
    }

    /**
     * watch restarted on a robot's log that already holds a finished faulty run (and a nominal one): the history goes
     * to the verdict, not to the robot. The next run, written after the start, warns and violates: one call each.
     */
    @Test
    @Timeout(60)
    void aRestartSendsNothingOfTheLogsHistoryAndEachLiveEventOnce() throws Exception {
        SimOptions o = SimOptions.defaults();
        List<SimRun> day = Day.simulate(List.of(Scenario.DEPLETED, Scenario.DIRECT, Scenario.DEPLETED), 51, 3, o);
        Path robot = Files.writeString(dir.resolve("robot.log"),
                LogWriter.toText(day.get(0), o) + LogWriter.toText(day.get(1), o));
        Path calls = dir.resolve("calls");
        Cli.Running watch = Cli.start("watch", "--log", robot.toString(), "--models", MODELS.toString(), "--json",
                "--on-warning", "echo warning $PREDMON_RUN $PREDMON_PROPERTY >> '" + calls + "'",
                "--on-violation", "echo violation $PREDMON_RUN $PREDMON_PROPERTY >> '" + calls + "'");
        awaitOutput(watch, "\"run\":1,\"time\""); // the history is read: run 0's warning, violations, then run 1
        assertTrue(watch.out().toString().contains("\"event\":\"warning\""), "the history's warning is shown");
        Thread.sleep(1000); // time for a hook command, were one started
        assertFalse(Files.exists(calls), "no hook for the history: " + (Files.exists(calls) ? Files.readString(calls)
                : ""));
        Files.writeString(robot, LogWriter.toText(day.get(2), o), StandardOpenOption.APPEND);
        // a depleted run is warned of its battery and its navigation, violates the battery's floor, then its
        // navigation aborts (no-abort): in run 0 and in run 2
        awaitOutput(watch, "\"event\":\"violation\",\"time\"", 4);
        long deadline = System.currentTimeMillis() + 10_000;
        while (System.currentTimeMillis() < deadline
                && (!Files.exists(calls) || Files.readAllLines(calls).size() < 4)) {
            Thread.sleep(20);
        }
        Thread.sleep(300);
        watch.stop();
        // once each; the two commands run side by side, so either may write first
        assertEquals(List.of("violation 2 battery", "violation 2 no-abort", "warning 2 battery", "warning 2 no-abort"),
                Files.readAllLines(calls).stream().sorted().toList(),
                watch.out().toString());
        assertEquals(ExitCodes.WARNING, watch.code().get(), watch.err().toString());
    }

    /** Waits until {@code text} occurs at least {@code times} times in what {@code watch} printed. */
    private static void awaitOutput(Cli.Running watch, String text, int times) throws InterruptedException {
        long deadline = System.currentTimeMillis() + 20_000;
        while (System.currentTimeMillis() < deadline && count(watch.out().toString(), text) < times) {
            Thread.sleep(20);
        }
        assertTrue(count(watch.out().toString(), text) >= times, text + " in " + watch.out());
    }

    private static void awaitOutput(Cli.Running watch, String text) throws InterruptedException {
        awaitOutput(watch, text, 1);
    }

    private static int count(String s, String part) {
        int n = 0;
        for (int at = s.indexOf(part); at >= 0; at = s.indexOf(part, at + 1)) {
            n++;
        }
        return n;
    }

    private static boolean onPath(String program) {
        String path = System.getenv("PATH");
        return path != null && Arrays.stream(path.split(File.pathSeparator))
                .anyMatch(d -> Files.isExecutable(Path.of(d, program)));
    }
}
