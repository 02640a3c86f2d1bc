package dev.predmon.simulate;

import dev.predmon.parse.RecordKind;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every seed tells its scenario's story, checked on the events alone (not on the simulator's own facts):
 * the level replies, the goTo commands and the isAtLocation replies.
 */
class SimulatorStoryTest {

    private static final double EW = SimOptions.DEFAULT_EARLY_WARNING;

    /** What the messages of one run show. */
    private record Story(double minLevel, double turnLevel, double firstBelow20Time, double firstGoToStation,
                         double atStation, double stationLevel, boolean chargedFull, boolean charging,
                         double atKitchen, boolean haltAfterKitchen) {

        static Story of(List<SimEvent> events) {
            double min = Double.MAX_VALUE;
            double turn = Double.NaN;
            double below = Double.NaN;
            double goToStation = Double.NaN;
            double atStation = Double.NaN;
            double stationLevel = Double.NaN;
            double last = Double.NaN;
            boolean full = false;
            boolean charging = false;
            double atKitchen = Double.NaN;
            boolean halt = false;
            for (int i = 0; i < events.size(); i++) {
                SimEvent e = events.get(i);
                if (e.kind() == RecordKind.COMMAND && e.command().equals("goTo")
                        && e.argument().equals("charging_station") && Double.isNaN(goToStation)) {
                    goToStation = e.time();
                }
                if (e.kind() != RecordKind.REPLY) {
                    continue;
                }
                switch (e.command()) {
                    case "level" -> {
                        double v = Double.parseDouble(e.reply());
                        min = Math.min(min, v);
                        last = v;
                        if (Double.isNaN(turn) && v <= EW) {
                            turn = v;
                        }
                        if (Double.isNaN(below) && v < 20.0) {
                            below = e.time();
                        }
                        full |= !Double.isNaN(atStation) && v == 100.0;
                    }
                    case "charging_status" -> charging |= e.reply().equals("1");
                    case "isAtLocation" -> {
                        if (e.reply().equals("1") && e.argument().equals("charging_station")
                                && Double.isNaN(atStation)) {
                            atStation = e.time();
                            stationLevel = last;
                        }
                        if (e.reply().equals("1") && e.argument().equals("kitchen") && Double.isNaN(atKitchen)) {
                            atKitchen = e.time();
                            halt = events.subList(i + 1, events.size()).stream()
                                    .filter(x -> x.kind() == RecordKind.COMMAND && x.protocol().equals("GoTo"))
                                    .findFirst()
                                    .map(x -> x.command().equals("halt") && x.argument().equals("kitchen"))
                                    .orElse(false);
                        }
                    }
                    default -> {
                    }
                }
            }
            return new Story(min, turn, below, goToStation, atStation, stationLevel, full, charging, atKitchen,
                    halt);
        }
    }

    @Test
    void directReachesTheKitchenAboveTheEarlyWarning() {
        for (SimRun run : Runs.of(Scenario.DIRECT)) {
            Story s = Story.of(run.events());
            String seed = "seed " + run.seed();
            assertTrue(s.minLevel() > EW, seed);
            assertTrue(Double.isNaN(s.firstGoToStation()), seed);
            assertFalse(Double.isNaN(s.atKitchen()), seed);
            assertTrue(s.haltAfterKitchen(), seed + ": isAt kitchen true must be followed by halt(kitchen)");
            assertNull(run.truth().violationTime(), seed);
        }
    }

    @Test
    void rechargeChargesToFullAndNeverGoesBelow20() {
        double lowestArrival = 100;
        double highestArrival = 0;
        for (SimRun run : Runs.of(Scenario.RECHARGE)) {
            Story s = Story.of(run.events());
            String seed = "seed " + run.seed();
            assertTrue(s.turnLevel() <= EW, seed);
            assertTrue(s.firstGoToStation() < s.atStation(), seed);
            assertTrue(s.stationLevel() >= 30.0, seed);
            assertTrue(s.charging() && s.chargedFull(), seed);
            assertTrue(s.atKitchen() > s.atStation(), seed);
            assertTrue(s.haltAfterKitchen(), seed);
            assertTrue(s.minLevel() >= 20.0, seed);
            assertNull(run.truth().violationTime(), seed);
            lowestArrival = Math.min(lowestArrival, s.stationLevel());
            highestArrival = Math.max(highestArrival, s.stationLevel());
        }
        assertTrue(lowestArrival < 35 && highestArrival > 44,
                "station arrival levels should spread over 30..48, got " + lowestArrival + ".." + highestArrival);
    }

    @Test
    void depletedFallsBelow20BeforeReachingTheStation() {
        double lowestTurn = 100;
        double highestTurn = 0;
        for (SimRun run : Runs.of(Scenario.DEPLETED)) {
            Story s = Story.of(run.events());
            String seed = "seed " + run.seed();
            assertTrue(s.turnLevel() <= EW && s.turnLevel() >= 20.0, seed);
            assertTrue(s.firstGoToStation() < s.firstBelow20Time(), seed);
            assertTrue(Double.isNaN(s.atStation()), seed + ": must not reach the station");
            assertEquals(0.0, s.minLevel(), seed);
            assertNotNull(run.truth().violationTime(), seed);
            assertTrue(run.truth().faulty(), seed);
            lowestTurn = Math.min(lowestTurn, s.turnLevel());
            highestTurn = Math.max(highestTurn, s.turnLevel());
        }
        assertTrue(highestTurn - lowestTurn > 4, "turn levels should vary, got " + lowestTurn + ".." + highestTurn);
    }

    @Test
    void earlyWarningOptionMovesTheTurn() {
        SimOptions thirty = SimOptions.defaults().withEarlyWarning(30);
        for (long seed = 1; seed <= 20; seed++) {
            SimRun run = Simulator.run(Scenario.RECHARGE, seed, thirty);
            assertTrue(run.truth().turnLevel() <= 30 && run.truth().turnLevel() > 21, "seed " + seed);
            assertTrue(run.truth().batteryTimeline().stream().allMatch(p -> p[1] >= 20), "seed " + seed);
        }
    }

    @Test
    void timesIncreaseAndEveryCommandIsAnsweredBeforeItsConnectionIsUsedAgain() {
        for (Scenario sc : Scenario.values()) {
            for (SimRun run : Runs.of(sc).subList(0, 20)) {
                List<SimEvent> ev = run.events();
                for (int i = 1; i < ev.size(); i++) {
                    assertTrue(ev.get(i).timeMicros() > ev.get(i - 1).timeMicros(), "seed " + run.seed() + " #" + i);
                }
                for (int i = 0; i < ev.size(); i++) {
                    if (ev.get(i).kind() == RecordKind.COMMAND) {
                        SimEvent reply = ev.get(i + 1);
                        assertEquals(RecordKind.REPLY, reply.kind());
                        assertEquals(ev.get(i).client(), reply.client());
                        assertEquals(ev.get(i).command(), reply.command());
                    }
                }
            }
        }
    }
}
