package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Following as people expect: a line when a log is found and followed, a heartbeat with the latest forecast, and the
 * wall-clock time on text lines and in every JSON event.
 */
class FollowingLinesTest {

    private static final Path MODELS = Path.of("models");
    private static final String WALL_TIME = "\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\d\\.\\d{3}Z";

    @TempDir
    Path dir;

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long deadline = System.currentTimeMillis() + 20_000;
        while (System.currentTimeMillis() < deadline && !condition.getAsBoolean()) {
            Thread.sleep(20);
        }
        assertTrue(condition.getAsBoolean(), what);
    }

    @Test
    @Timeout(60)
    void aLineSaysWhenALogIsFollowedAndWhenAWaitedForOneAppears() throws Exception {
        Path present = Files.writeString(dir.resolve("robot-1.log"), FleetWatchTest.run(Scenario.RECHARGE, 9002));
        Path later = dir.resolve("robot-2.log");
        Cli.Running w = Cli.start("watch", "--log", present.toString(), "--log", later.toString(), "--models",
                MODELS.toString());
        await(() -> w.err().toString().contains("waiting for " + later + " to appear"), w.err().toString());
        await(() -> w.err().toString().contains("predmon: following " + present + "\n"), w.err().toString());
        Files.writeString(later, FleetWatchTest.run(Scenario.DEPLETED, 9001));
        await(() -> w.err().toString().contains("predmon: " + later + " appeared; following it\n"),
                w.err().toString());
        await(() -> w.out().toString().contains("WARNING"), w.out().toString());
        w.stop();
        assertEquals(1, w.err().toString().lines().filter(l -> l.contains("appeared")).count(), "once");
    }

    @Test
    @Timeout(60)
    void heartbeatsTellTheLatestForecastOfAQuietLog() throws Exception {
        Path log = Files.writeString(dir.resolve("robot-1.log"), FleetWatchTest.run(Scenario.RECHARGE, 9002));
        Cli.Running text = Cli.start("watch", "--log", log.toString(), "--models", MODELS.toString(), "--heartbeat",
                "200ms", "--timestamps");
        await(() -> text.out().toString().lines().filter(l -> l.contains("heartbeat")).count() >= 3,
                text.out().toString());
        text.stop();
        List<String> beats = text.out().toString().lines().filter(l -> l.contains("heartbeat")).toList();
        for (String beat : beats) {
            assertTrue(beat.matches(WALL_TIME + " heartbeat: line \\d+, run 0, \\d+ records; forecast: P\\(violation\\) "
                    + ".*"), beat);
        }
        Instant first = Instant.parse(beats.get(0).substring(0, 24));
        Instant third = Instant.parse(beats.get(2).substring(0, 24));
        long apart = Duration.between(first, third).toMillis();
        assertTrue(apart >= 350 && apart < 2000, "every 200 ms: " + beats);

        Cli.Running json = Cli.start("watch", "--log", log.toString(), "--models", MODELS.toString(), "--heartbeat",
                "0.2", "--json");
        await(() -> json.out().toString().contains("\"event\":\"heartbeat\""), json.out().toString());
        json.stop();
        JsonNode beat = new Cli(0, json.out().toString(), "").jsonLines().stream()
                .filter(e -> e.get("event").asText().equals("heartbeat")).findFirst().orElseThrow();
        assertTrue(beat.get("present").asBoolean() && beat.get("line").asLong() > 0, beat.toString());
        assertTrue(beat.get("forecast").get("probability").isNumber(), beat.toString());
    }

    @Test
    void everyJsonEventCarriesTheWallClockTimeAndTextLinesDoWithTimestamps() throws Exception {
        Path log = Files.writeString(dir.resolve("robot-1.log"), FleetWatchTest.run(Scenario.DEPLETED, 9001));
        Instant before = Instant.now().minusMillis(1);
        Cli json = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow", "--json");
        List<JsonNode> events = json.jsonLines();
        assertTrue(events.size() > 3 && events.stream().anyMatch(e -> e.get("event").asText().equals("end")),
                json.out());
        for (JsonNode e : events) {
            String at = e.get("wallTime").asText();
            assertTrue(at.matches(WALL_TIME), e.toString());
            assertTrue(!Instant.parse(at).isBefore(before) && !Instant.parse(at).isAfter(Instant.now()), at);
        }
        Cli text = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow",
                "--timestamps");
        List<String> lines = text.out().lines().filter(l -> l.contains("WARNING") || l.contains("VIOLATION")
                || l.contains("end of")).toList();
        // the battery's warning and violation, the aborted navigation's (no-abort) warning and violation, the end
        assertEquals(5, lines.size(), text.out());
        lines.forEach(l -> assertTrue(l.matches(WALL_TIME + " .*"), l));
        assertTrue(Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow").out()
                .startsWith("t="), "no time stamp without --timestamps");
    }

    @Test
    void aHeartbeatMustBeADurationOfAFollowedLog() throws Exception {
        Path log = Files.writeString(dir.resolve("robot-1.log"), FleetWatchTest.run(Scenario.DEPLETED, 9001));
        for (String bad : List.of("0", "soon", "-1s", "5x")) {
            Cli r = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--heartbeat", bad);
            assertEquals(ExitCodes.USAGE, r.code(), bad + ": " + r.err());
            assertTrue(r.err().contains("--heartbeat must be a duration"), r.err());
        }
        Cli r = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--heartbeat", "1m",
                "--no-follow");
        assertEquals(ExitCodes.USAGE, r.code(), r.err());
    }
}
