package dev.predmon.simulate;

import dev.predmon.simulate.Novelties.AbortOn;
import dev.predmon.simulate.Novelties.Span;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.HashSet;
import java.util.HexFormat;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Each novelty shows in the written log as a reader of it would see it, leaves the run's scenario (nominal or
 * faulty) as it was, and is told by the truth; without novelties the logs are those simulate always wrote.
 */
class NoveltiesTest {

    private static SimOptions with(Novelties n) {
        return SimOptions.defaults().withNovelties(n);
    }

    private static List<Runs.Rec> records(SimRun run) {
        return Runs.read(LogWriter.toText(run, run.options()));
    }

    private static boolean isStatus(Runs.Rec r, String location, String reply) {
        return r.kind().equals("Reply") && r.command().equals("getStatus") && r.args().equals(location)
                && r.reply().equals(reply);
    }

    private static boolean isGoTo(Runs.Rec r, String location) {
        return r.kind().equals("Command") && r.command().equals("goTo") && r.args().equals(location);
    }

    @Test
    void aBlockedPathAbortsAndTheTreeSendsGoToAgain() {
        SimOptions o = with(Novelties.NONE.withAborts(1, AbortOn.ANY));
        int retried = 0;
        for (Scenario s : Scenario.values()) {
            for (long seed = 1; seed <= 8; seed++) {
                SimRun run = Simulator.run(s, seed, o);
                String id = s.id() + " seed " + seed;
                List<NoveltyTruth.Abort> aborts = run.truth().novelties().aborts();
                assertEquals(1, aborts.size(), id);
                NoveltyTruth.Abort a = aborts.get(0);
                double tick = run.truth().parameters().tickPeriod();
                assertTrue(a.abortTime() - a.stuckFrom() >= 10 - tick && a.abortTime() - a.stuckFrom() <= 40 + tick,
                        id + ": stuck " + (a.abortTime() - a.stuckFrom()) + " s");
                List<Runs.Rec> recs = records(run);
                Runs.Rec abort = recs.stream().filter(r -> isStatus(r, a.location(), "3")).findFirst().orElseThrow();
                assertEquals(a.abortTime(), abort.time(), id + ": the truth's abort is the first ABORT reply");
                // The tree sends goTo again at the next tick: to the same place, or to the charging station when
                // the battery reached the early warning meanwhile.
                Runs.Rec next = recs.stream().filter(r -> r.kind().equals("Command") && r.command().equals("goTo")
                        && r.time() > a.abortTime()).findFirst().orElseThrow();
                assertTrue(next.time() - a.abortTime() <= 2 * tick, id + ": goTo again at the next tick");
                if (a.retryTime() != null) {
                    assertEquals(a.location(), next.args(), id);
                    assertEquals(a.retryTime(), next.time(), id);
                    retried++;
                } else {
                    assertEquals(Components.CHARGING_STATION, next.args(), id);
                    assertTrue(recs.stream().noneMatch(r -> isGoTo(r, a.location()) && r.time() > a.abortTime()), id);
                }
                // While stuck, the navigation reports RUNNING and the robot is not there.
                assertTrue(recs.stream().filter(r -> r.time() > a.stuckFrom() && r.time() < a.abortTime()
                                && r.kind().equals("Reply") && r.command().equals("getStatus"))
                        .allMatch(r -> r.reply().equals("1")), id);
                assertEquals(s.faulty(), run.truth().violationTime() != null, id + ": the outcome stays the scenario's");
            }
        }
        assertTrue(retried >= 20, "most aborted navigations are retried: " + retried + " of 24");
    }

    @Test
    void aRechargeRunBlockedOnItsWayToTheStationStillRechargesAndStaysAbove20() {
        SimOptions o = with(Novelties.NONE.withAborts(1, AbortOn.STATION));
        for (long seed = 1; seed <= 8; seed++) {
            SimRun run = Simulator.run(Scenario.RECHARGE, seed, o);
            NoveltyTruth.Abort a = run.truth().novelties().aborts().get(0);
            assertEquals(Components.CHARGING_STATION, a.location());
            assertNull(run.truth().violationTime(), "seed " + seed);
            assertTrue(run.truth().batteryTimeline().stream().allMatch(p -> p[1] >= 20.0), "seed " + seed);
            assertTrue(run.truth().batteryTimeline().stream().anyMatch(p -> p[0] > a.abortTime() && p[1] == 100.0),
                    "seed " + seed + ": charged to full after the retry");
        }
    }

    @Test
    void aDepletedRunBlockedOnItsWayToTheStationViolatesAsTheRealRobotDid() {
        SimOptions o = with(Novelties.NONE.withAborts(1, AbortOn.STATION));
        for (long seed = 1; seed <= 8; seed++) {
            SimRun run = Simulator.run(Scenario.DEPLETED, seed, o);
            NoveltyTruth.Abort a = run.truth().novelties().aborts().get(0);
            assertEquals(Components.CHARGING_STATION, a.location());
            assertTrue(run.truth().faulty());
            assertNotNull(run.truth().violationTime(), "seed " + seed);
            assertTrue(a.stuckFrom() > run.truth().turnTime(), "seed " + seed + ": stuck after turning to the station");
        }
    }

    @Test
    void directRunsNeverGoToTheStationSoNothingAbortsThere() {
        SimOptions o = with(Novelties.NONE.withAborts(2, AbortOn.STATION));
        for (long seed = 1; seed <= 5; seed++) {
            SimRun run = Simulator.run(Scenario.DIRECT, seed, o);
            assertEquals(List.of(), run.truth().novelties().aborts());
            assertTrue(records(run).stream().noneMatch(r -> r.command().equals("getStatus") && r.reply().equals("3")));
        }
    }

    @Test
    void twoAbortsOnTheWayToTheDestinationAndAFixedStuckTime() {
        SimOptions o = with(Novelties.NONE.withAborts(2, AbortOn.DESTINATION).withStuck(new Span(15, 15)));
        for (long seed = 1; seed <= 5; seed++) {
            SimRun run = Simulator.run(Scenario.DIRECT, seed, o);
            List<NoveltyTruth.Abort> aborts = run.truth().novelties().aborts();
            assertEquals(2, aborts.size());
            double tick = run.truth().parameters().tickPeriod();
            for (NoveltyTruth.Abort a : aborts) {
                assertEquals(Components.KITCHEN, a.location());
                double stuck = a.abortTime() - a.stuckFrom();
                assertTrue(stuck >= 15 - 0.01 && stuck <= 15 + 2 * tick, "seed " + seed + ": " + stuck);
            }
            assertEquals(3, records(run).stream().filter(r -> isGoTo(r, Components.KITCHEN)).count());
        }
    }

    /** The travel from the first goTo to the destination, and the battery it cost. */
    private static double[] trip(SimRun run) {
        double goTo = Double.NaN;
        double first = Double.NaN;
        double level = Double.NaN;
        for (Runs.Rec r : records(run)) {
            if (r.kind().equals("Reply") && r.command().equals("level")) {
                level = Double.parseDouble(r.reply());
                first = Double.isNaN(first) ? level : first;
            }
            if (Double.isNaN(goTo) && r.kind().equals("Command") && r.command().equals("goTo")) {
                goTo = r.time();
            }
            if (r.kind().equals("Reply") && r.command().equals("isAtLocation") && r.reply().equals("1")) {
                return new double[] {r.time() - goTo, first - level};
            }
        }
        throw new AssertionError("never arrives");
    }

    @Test
    void aSlowerRobotTakesTwiceAsLongAndABatteryThatDrainsFasterLosesMore() {
        SimOptions slow = with(Novelties.NONE.withSlowdown(new Span(2, 2)));
        SimOptions drain = with(Novelties.NONE.withDrainFactor(new Span(1.5, 1.5)));
        int sameWorld = 0;
        for (SimRun plain : Runs.of(Scenario.DIRECT).subList(0, 20)) {
            SimRun slowed = Simulator.run(Scenario.DIRECT, plain.seed(), slow);
            SimRun drained = Simulator.run(Scenario.DIRECT, plain.seed(), drain);
            assertEquals(2.0, slowed.truth().novelties().slowdown());
            assertEquals(1.5, drained.truth().novelties().drainFactor());
            double tick = plain.truth().parameters().tickPeriod();
            if (slowed.truth().parameters().attempt() == plain.truth().parameters().attempt()
                    && drained.truth().parameters().attempt() == plain.truth().parameters().attempt()) {
                sameWorld++; // the same sample of the world: the novelty is all that differs
                assertEquals(plain.truth().parameters().speed() / 2, slowed.truth().parameters().speed(), 1e-12);
                assertEquals(2 * trip(plain)[0], trip(slowed)[0], 3 * tick, "seed " + plain.seed());
                assertEquals(1.5 * trip(plain)[1], trip(drained)[1], 1e-6, "seed " + plain.seed());
            }
            assertTrue(slowed.truth().turnTime() == null && drained.truth().turnTime() == null,
                    "still direct: the battery never falls to the early warning");
        }
        assertTrue(sameWorld >= 5, "too few seeds keep their world: " + sameWorld);
    }

    @Test
    void aRangeOfFactorsIsDrawnPerRunFromTheSeed() {
        SimOptions o = with(Novelties.NONE.withSlowdown(new Span(1.2, 2.0)));
        Set<Double> drawn = new HashSet<>();
        for (long seed = 1; seed <= 10; seed++) {
            double f = Simulator.run(Scenario.DEPLETED, seed, o).truth().novelties().slowdown();
            assertTrue(f >= 1.2 && f <= 2.0, "seed " + seed + ": " + f);
            assertEquals(f, Simulator.run(Scenario.DEPLETED, seed, o).truth().novelties().slowdown());
            drawn.add(f);
        }
        assertEquals(10, drawn.size());
    }

    @Test
    void aNewLocationReplacesTheKitchenEverywhere() {
        SimOptions o = with(Novelties.NONE.withNewLocation("office"));
        for (Scenario s : Scenario.values()) {
            SimRun run = Simulator.run(s, 3, o);
            String text = LogWriter.toText(run, o);
            assertFalse(text.contains("kitchen"), s.id());
            assertTrue(text.contains("  To        : /GoToComponent\n  Protocol  : GoTo\n  Command   : goTo\n"
                    + "  Arguments : office\n"), s.id());
            assertTrue(text.contains("  From      : /GoToIsAtClient/office\n"), s.id());
            assertEquals("office", run.truth().novelties().destination());
            assertEquals(s.faulty(), run.truth().violationTime() != null, s.id());
            boolean arrives = records(run).stream().anyMatch(r -> r.kind().equals("Reply")
                    && r.command().equals("isAtLocation") && r.args().equals("office") && r.reply().equals("1"));
            assertEquals(!s.faulty(), arrives, s.id() + ": nominal runs reach the new location");
        }
    }

    @Test
    void withoutTicksTheLogIsTheSameRunWithTheTickRecordsLeftOut() {
        SimOptions o = with(Novelties.NONE.withNoTicks(true));
        for (Scenario s : Scenario.values()) {
            SimRun plain = Simulator.run(s, 5, SimOptions.defaults());
            SimRun run = Simulator.run(s, 5, o);
            assertEquals(plain.events(), run.events(), "the same simulated run");
            String expected = LogWriter.toText(plain, SimOptions.defaults())
                    .replaceAll("\\d+\\.\\d{6}\tDEBUG\tTick intercepted:\n(  .*\n){6}", "");
            String text = LogWriter.toText(run, o);
            assertFalse(text.contains("Tick"));
            assertEquals(expected, text);
            assertFalse(run.truth().novelties().ticks());
            assertEquals(Runs.read(text).get(0).time(), run.truth().novelties().startTime());
        }
    }

    /**
     * The default logs and truths of seeds 1..4 and of a three-scenario day, digested: simulate wrote exactly these
     * bytes before novelties existed, and must go on doing so. The truth's {@code properties}, its last field, came
     * later: it is left out of the digest ({@link PropertyTruthTest} checks it).
     */
    @Test
    void withoutNoveltiesTheLogsAndTruthsAreByteForByteThoseOfBefore() throws Exception {
        SimOptions o = SimOptions.defaults();
        MessageDigest sha = MessageDigest.getInstance("SHA-256");
        for (Scenario s : List.of(Scenario.DIRECT, Scenario.RECHARGE, Scenario.DEPLETED)) {
            for (long seed = 1; seed <= 4; seed++) {
                SimRun run = Simulator.run(s, seed, o);
                sha.update(LogWriter.toText(run, o).getBytes(StandardCharsets.UTF_8));
                sha.update((withoutProperties(TruthWriter.toJson(run.truth())) + "\n").getBytes(StandardCharsets.UTF_8));
            }
        }
        List<SimRun> day = Day.simulate(List.of(Scenario.DIRECT, Scenario.DEPLETED, Scenario.RECHARGE), 3, 5, o);
        StringBuilder truths = new StringBuilder("[");
        for (SimRun run : day) {
            sha.update(LogWriter.toText(run, o).getBytes(StandardCharsets.UTF_8));
            truths.append(truths.length() > 1 ? ",\n" : "\n").append(withoutProperties(TruthWriter.toJson(run.truth())));
        }
        sha.update(truths.append("\n]\n").toString().getBytes(StandardCharsets.UTF_8));
        assertEquals("8056aa8150846ec51d9fe3131af9fa38b6d9967f89a97d539f371e82030e3096",
                HexFormat.of().formatHex(sha.digest()));
    }

    /** A truth's JSON without its last field, {@code properties}. */
    private static String withoutProperties(String json) {
        String cut = json.replaceFirst("(?s),\\s*\"properties\" : \\{.*}\\s*}$", "\n}");
        assertFalse(cut.equals(json), "the truth ends with its properties");
        return cut;
    }
}
