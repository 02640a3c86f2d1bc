package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbridge.FakeRosbridge;
import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code watch --rosbridge} against a rosbridge-protocol server the test starts, which replays a simulated nav2 run
 * (the battery draining below 20%, navigation goals, an abort) as publish ops: the same warnings and violations, at
 * the same lines and times, as {@code watch} on the same messages written to an MCAP recording; each property's
 * verdict published on /diagnostics; a dropped connection said once and made again.
 */
class RosbridgeWatchTest {

    private static final List<String> NAV2_TOPICS = List.of("/battery_state", "/navigate_to_pose/_action/status",
            "/dock_robot/_action/status");

    @TempDir
    Path dir;

    private FakeRosbridge server;

    @AfterEach
    void stop() throws InterruptedException {
        FakeRosbridge.replayClock(null);
        if (server != null) {
            server.stop(1000);
        }
    }

    private static Cli.Running watch(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        AtomicInteger code = new AtomicInteger(-1);
        Thread t = new Thread(() -> {
            picocli.CommandLine cl = Main.commandLine();
            cl.setOut(new PrintWriter(out, true));
            cl.setErr(new PrintWriter(err, true));
            code.set(cl.execute(args));
        });
        t.start();
        return new Cli.Running(t, out, err, code);
    }

    private static void await(BooleanSupplier done, String what) throws InterruptedException {
        long until = System.nanoTime() + 20_000_000_000L;
        while (!done.getAsBoolean()) {
            if (System.nanoTime() > until) {
                throw new AssertionError("timed out waiting for " + what);
            }
            Thread.sleep(10);
        }
    }

    /** The event lines of a watch's output: warnings and violations, with their lines and times. */
    private static List<String> events(String out) {
        return out.lines().filter(l -> l.startsWith("t=")).toList();
    }

    @Test
    void aReplayedRunGetsTheRecordingsWarningsAndVerdictsAndTheDiagnosticsShowThem() throws Exception {
        Path models = Nav2Runs.models();
        List<BagMessage> run = Nav2Runs.messages(Scenario.DEPLETED, 11);
        Path bag = dir.resolve("depleted-11.mcap");
        Nav2Runs.write(bag, run);
        Cli fromBag = Cli.run("watch", "--no-follow", "--models", models.toString(), "--log", bag.toString());
        List<String> expected = events(fromBag.out());
        assertTrue(expected.stream().anyMatch(l -> l.contains("VIOLATION of 'battery at least 20%'")), fromBag.out());

        server = new FakeRosbridge();
        String url = server.begin();
        FakeRosbridge.replayClock(FakeRosbridge.times(run));
        Cli.Running live = watch("watch", "--models", models.toString(), "--rosbridge", url,
                "--publish-diagnostics");
        try {
            await(() -> server.subscribed(NAV2_TOPICS), "the subscriptions");
            await(() -> !server.published.getOrDefault("/diagnostics", List.of()).isEmpty(), "diagnostics");
            JsonNode first = server.published.get("/diagnostics").get(0);
            first.get("status").forEach(s -> assertEquals(3, s.get("level").asInt(),
                    "no evidence before any message: STALE " + s));
            for (BagMessage m : run) {
                assertEquals(1, server.publish(m));
            }
            String last = expected.get(expected.size() - 1);
            await(() -> live.out().toString().contains(last.substring(0, last.indexOf(':'))), "the last event");
            Thread.sleep(200);
            assertEquals(expected, events(live.out().toString()), live.err().toString());

            List<String> warnings = expected.stream().filter(l -> l.contains("WARNING")).toList();
            assertTrue(!warnings.isEmpty() && expected.indexOf(warnings.get(0))
                    < expected.indexOf(expected.stream().filter(l -> l.contains("VIOLATION of 'battery")).findFirst()
                    .orElseThrow()), "the warning comes before the violation: " + expected);

            await(() -> levels(server, "battery at least 20%").contains(2), "battery ERROR on /diagnostics");
            List<Integer> battery = levels(server, "battery at least 20%");
            assertEquals(3, battery.get(0));
            assertTrue(battery.indexOf(1) > 0 && battery.indexOf(1) < battery.indexOf(2),
                    "STALE, then WARN at the warning, then ERROR at the violation: " + battery);
            assertTrue(levels(server, "a navigation never aborts").contains(2), "the abort is an ERROR");
            assertTrue(server.advertised.contains("/diagnostics diagnostic_msgs/msg/DiagnosticArray"),
                    String.valueOf(server.advertised));

            // The connection drops: said once, made again, subscribed again; nothing judged meanwhile.
            int before = server.subscribes.size();
            server.dropAll();
            await(() -> server.subscribes.size() >= before + NAV2_TOPICS.size(), "the subscriptions again");
            await(() -> live.err().toString().contains("connected again"), "the reconnection said");
            String err = live.err().toString();
            assertEquals(1, err.lines().filter(l -> l.contains("connection lost")).count(), err);
            // nothing judged across the gap: the run ends there, and the alarms still up (the battery's violation)
            // end with it, as at the end of any run: never told as a recovery of the property
            await(() -> live.out().toString().contains("the connection to the robot was lost and made again: "
                    + "monitoring starts over"), "the new run said");
            List<String> got = events(live.out().toString());
            assertEquals(expected, got.subList(0, Math.min(expected.size(), got.size())), "no verdict while disconnected");
            List<String> after = got.subList(expected.size(), got.size());
            assertFalse(after.isEmpty(), "the violated battery's alarm ends with the run: " + got);
            assertTrue(after.stream().allMatch(l -> l.contains(": ALARM ENDS WITH ITS RUN: ") && l.endsWith(
                    ": the run ended: the connection to the robot was lost and made again; what follows is a new run")),
                    after.toString());
            assertTrue(after.stream().anyMatch(l -> l.contains("(battery)")), after.toString());
        } finally {
            live.stop();
        }
        assertFalse(live.out().toString().isEmpty());
    }

    /**
     * With {@code --rosbridge-compression cbor-raw} every subscription asks for cbor-raw, every message comes as a
     * binary CBOR frame around its CDR bytes, and the events are the recording's, line for line.
     */
    @Test
    void cborRawFramesGiveTheRecordingsEvents() throws Exception {
        Path models = Nav2Runs.models();
        List<BagMessage> run = Nav2Runs.messages(Scenario.DEPLETED, 12);
        Path bag = dir.resolve("depleted-12.mcap");
        Nav2Runs.write(bag, run);
        List<String> expected = events(Cli.run("watch", "--no-follow", "--models", models.toString(), "--log",
                bag.toString()).out());
        assertTrue(expected.stream().anyMatch(l -> l.contains("WARNING")), expected.toString());

        server = new FakeRosbridge();
        String url = server.begin();
        FakeRosbridge.replayClock(FakeRosbridge.times(run));
        Cli.Running live = watch("watch", "--models", models.toString(), "--rosbridge", url,
                "--rosbridge-compression", "cbor-raw");
        try {
            await(() -> server.subscribed(NAV2_TOPICS), "the subscriptions");
            assertTrue(!server.compressions.isEmpty() && server.compressions.stream().allMatch("cbor-raw"::equals),
                    server.compressions.toString());
            for (BagMessage m : run) {
                assertEquals(1, server.publish(m));
            }
            assertEquals(run.size(), server.binaryFrames.get(), "every message a binary frame");
            String last = expected.get(expected.size() - 1);
            await(() -> live.out().toString().contains(last.substring(0, last.indexOf(':'))), "the last event");
            Thread.sleep(200);
            assertEquals(expected, events(live.out().toString()), live.err().toString());
        } finally {
            live.stop();
        }

        Cli noServer = Cli.run("watch", "--models", models.toString(), "--log", bag.toString(),
                "--rosbridge-compression", "cbor-raw");
        assertEquals(ExitCodes.USAGE, noServer.code(), noServer.err());
        assertTrue(noServer.err().contains("give --rosbridge"), noServer.err());
    }

    /** The levels published for the property named {@code name}, in order. */
    private static List<Integer> levels(FakeRosbridge server, String name) {
        return server.published.getOrDefault("/diagnostics", List.of()).stream()
                .flatMap(a -> java.util.stream.StreamSupport.stream(a.get("status").spliterator(), false))
                .filter(s -> s.get("name").asText().equals("predmon: " + name))
                .map(s -> s.get("level").asInt()).toList();
    }
}
