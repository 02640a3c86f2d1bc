package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.event.LogEvent;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;
import dev.predmon.support.Records;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A tile shows what an operator beside the robot needs, per run, in bounded memory. */
class TileTest {

    private static final Abstraction A = AbstractionFiles.defaults();
    private static ModelSet models;
    private final AtomicLong now = new AtomicLong(1_000_000);

    @BeforeAll
    static void shippedModels() throws Exception {
        models = ModelStore.read(Path.of("models"), A);
    }

    private Board board() {
        return new Board(models.models(), A.safety(), Duration.ofSeconds(10), now::get);
    }

    /** A battery reading as the safety monitor sees it (the reply of a level query), just after {@code time}. */
    private static LogRecord level(double time, double level) {
        return new Records().at(time).level(level).list().get(1);
    }

    private static MonitorEvent.Warning warning(double t, int run) {
        return new MonitorEvent.Warning(t, 70, List.of("depleted"), 27.8, 14, Clock.SECONDS, run);
    }

    private static MonitorEvent.Violation violation(double t, int run) {
        return new MonitorEvent.Violation(t, 90, "battery level >= 20%", 18.0, 21.0, Clock.SECONDS, run);
    }

    private static JsonNode snap(Board b, String log) {
        return b.status(log).get("logs").get(0);
    }

    @Test
    void theLightGoesGreyGreenYellowRedAndTheLeadAppearsOnceBothHappened() {
        Board b = board();
        Tile t = b.tile("robot.log");
        assertEquals("grey", snap(b, "robot.log").get("light").asText(), "no data yet");
        Judged.record(t, level(1, 80));
        assertEquals("green", snap(b, "robot.log").get("light").asText());
        b.event(t, LogEvent.of(t.log(), warning(30, 0)));
        JsonNode s = snap(b, "robot.log");
        assertEquals("yellow", s.get("light").asText());
        assertTrue(s.get("lead").isNull(), "no lead before the violation");
        Judged.record(t, level(35, 18));
        b.event(t, LogEvent.of(t.log(), violation(35, 0)));
        s = snap(b, "robot.log");
        assertEquals("red", s.get("light").asText());
        assertEquals(5.0, s.get("lead").asDouble(), 1e-9);
        assertEquals(18.0, s.get("value").asDouble());
        for (JsonNode o : List.of(s, s.get("warning"), s.get("violation"))) {
            assertEquals(o.get("value"), o.get("battery"), "the older name of value stays in /status: " + o);
        }
        assertEquals(18.0, s.get("violation").get("value").asDouble());
        assertEquals(2, s.get("series").size());
        assertEquals(List.of("warning", "violation"), events(s));
    }

    @Test
    void eliminatedModelsShowTheirReasonAndANewRunStartsOverKeepingTheVerdict() {
        Board b = board();
        Tile t = b.tile("day.log");
        LearnedModel first = models.models().get(0);
        Judged.record(t, level(1, 80));
        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Eliminated(2, 12, first.id(), first.scenario(), first.faulty(),
                "cannot take input x at step 3", Clock.SECONDS, 0)));
        b.event(t, LogEvent.of(t.log(), warning(30, 0)));
        JsonNode s = snap(b, "day.log");
        JsonNode m = s.get("models").get(0);
        assertFalse(m.get("alive").asBoolean());
        assertEquals("line 12: cannot take input x at step 3", m.get("reason").asText());
        assertEquals(models.models().size() - 1, count(s.get("models"), true));

        b.event(t, LogEvent.of(t.log(), new MonitorEvent.RunStarted(1, 100, 500, Clock.SECONDS)));
        s = snap(b, "day.log");
        assertEquals(1, s.get("run").asInt());
        assertEquals("grey", s.get("light").asText(), "the new run has no reading yet");
        assertEquals(0, s.get("series").size(), "the plot starts over");
        assertEquals(models.models().size(), count(s.get("models"), true), "every model starts over");
        JsonNode earlier = s.get("earlierRuns").get(0);
        assertEquals(0, earlier.get("run").asInt());
        assertTrue(earlier.get("warning").asBoolean() && !earlier.get("violation").asBoolean());
        assertEquals("yellow", earlier.get("light").asText());
        assertEquals(3, s.get("events").size(), "the last events go on across runs");

        b.event(t, LogEvent.of(t.log(), new MonitorEvent.Restarted("truncated")));
        s = snap(b, "day.log");
        assertEquals(2, s.get("run").asInt(), "a rotated log goes on in a new run, as the monitor numbers it");
        assertEquals(2, s.get("earlierRuns").size(), "the runs before the rotation stay, as in watch's summary");
    }

    @Test
    void aLogThatStopsGrowingIsStale() {
        Board b = board();
        Tile t = b.tile("a.log");
        Judged.record(t, level(1, 80));
        now.addAndGet(9_000);
        assertFalse(snap(b, "a.log").get("stale").asBoolean());
        now.addAndGet(1_000);
        assertTrue(snap(b, "a.log").get("stale").asBoolean(), "10 s without growth");
        b.grew(t);
        JsonNode s = snap(b, "a.log");
        assertFalse(s.get("stale").asBoolean());
        assertEquals(0.0, s.get("quietSeconds").asDouble());
        b.tile("never.log");
        now.addAndGet(60_000);
        assertFalse(snap(b, "never.log").get("stale").asBoolean(), "a log never written is waiting, not stale");
    }

    @Test
    void aTileStaysSmallHoweverLongTheLog() {
        Board b = board();
        Tile t = b.tile("long.log");
        LogRecord latest = null;
        for (int run = 0; run < 50; run++) {
            if (run > 0) {
                b.event(t, LogEvent.of(t.log(), new MonitorEvent.RunStarted(run, run * 1000.0, run * 100_000L, Clock.SECONDS)));
            }
            for (int i = 0; i < 2_000; i++) {
                latest = level(run * 1000.0 + i * 0.5, 100 - i * 0.04);
                Judged.record(t, latest);
            }
        }
        JsonNode s = snap(b, "long.log");
        assertTrue(s.get("series").size() <= Tile.PLOT_POINTS + 1, "plot points: " + s.get("series").size());
        JsonNode last = s.get("series").get(s.get("series").size() - 1);
        assertEquals(latest.time(), last.get(0).asDouble(), "the plot ends at the latest reading");
        assertEquals(Tile.EARLIER_RUNS, s.get("earlierRuns").size());
        assertEquals(49 - Tile.EARLIER_RUNS, s.get("earlierRunsOmitted").asInt());
        assertEquals(Tile.LAST_EVENTS, s.get("events").size());
    }

    private static List<String> events(JsonNode tile) {
        List<String> out = new ArrayList<>();
        tile.get("events").forEach(e -> out.add(e.get("event").asText()));
        return out;
    }

    private static long count(JsonNode models, boolean alive) {
        long n = 0;
        for (JsonNode m : models) {
            n += m.get("alive").asBoolean() == alive ? 1 : 0;
        }
        return n;
    }
}
