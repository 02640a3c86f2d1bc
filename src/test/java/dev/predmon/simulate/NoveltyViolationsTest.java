package dev.predmon.simulate;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.cli.SimulateCommand;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.simulate.Novelties.Span;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Each novelty that breaks one of the new properties does so where its truth says: the log, read back with the
 * project's parser, shows the navigation still running at its deadline, the grasp failing its allowed attempts, the
 * tree still heading elsewhere ten ticks after the battery fell below 30. Other properties keep their verdicts.
 */
class NoveltyViolationsTest {

    private static final int T = PropertyLimits.DEFAULT.navigationTicks();
    private static final int K = PropertyLimits.DEFAULT.graspAttempts();

    @TempDir
    Path dir;

    private static SimOptions with(Novelties n) {
        return SimOptions.defaults().withNovelties(n);
    }

    private static PropertyTruth verdict(SimRun run, String id) {
        return run.truth().properties().get(id);
    }

    @Test
    void aNavigationThatNeverArrivesIsStillRunningAtItsDeadline() throws IOException {
        SimOptions o = with(Novelties.NONE.withNeverArrives(new Span(T + 20, T + 200)));
        for (Scenario s : List.of(Scenario.DIRECT, Scenario.RECHARGE)) {
            for (long seed = 1; seed <= 4; seed++) {
                SimRun run = Simulator.run(s, seed, o);
                String id = s.id() + " seed " + seed;
                ReadBack log = ReadBack.write(dir.resolve(s.id() + seed + ".log"), o, run);
                PropertyTruth v = verdict(run, PropertyJudge.NAVIGATION_IN_TIME);
                assertTrue(v.violated(), id);
                LogRecord deadline = log.at(v.line());
                assertTrue(ReadBack.tick(deadline, v.tick()), id + ": the Tick of the deadline, got " + deadline);
                // The last trip to the kitchen began T ticks before, and the robot never got there.
                LogRecord goTo = log.records().stream().filter(r -> ReadBack.command(r, "goTo", "kitchen"))
                        .reduce((a, b) -> b).orElseThrow();
                assertEquals(v.tick() - T, log.tickOf(goTo), id);
                List<LogRecord> statuses = log.after(goTo.line()).stream()
                        .filter(r -> r.kind() == RecordKind.REPLY && r.command().equals("getStatus")).toList();
                assertTrue(statuses.size() >= T, id + ": getStatus every tick, " + statuses.size());
                assertTrue(statuses.stream().allMatch(r -> r.reply().equals("1")), id + ": RUNNING to the end");
                assertTrue(log.after(goTo.line()).stream().noneMatch(r -> ReadBack.reply(r, "isAtLocation", "1")
                        && r.arguments().equals("kitchen")), id + ": never at the kitchen");
                assertNotNull(run.truth().novelties().stuckForGood(), id);
                assertFalse(verdict(run, PropertyJudge.BATTERY).violated(), id);
                assertFalse(verdict(run, PropertyJudge.NO_ABORT).violated(), id);
                assertFalse(verdict(run, PropertyJudge.CHARGER_IN_TIME).violated(), id);
            }
        }
        // Without Tick records the deadline's line is that of the first message of its tick.
        SimOptions noTicks = with(o.novelties().withNoTicks(true));
        SimRun quiet = Simulator.run(Scenario.DIRECT, 2, noTicks);
        PropertyTruth v = verdict(quiet, PropertyJudge.NAVIGATION_IN_TIME);
        ReadBack log = ReadBack.write(dir.resolve("quiet.log"), noTicks, quiet);
        LogRecord first = log.at(v.line());
        assertTrue(first.time() > v.time() && first.time() - v.time() < 0.01, first + " right after " + v.time());
        assertTrue(log.before(v.line()).stream().allMatch(r -> r.time() < v.time()));
        // A depleted run never reaches its way to the tour location's end: it runs out of battery as always.
        SimRun depleted = Simulator.run(Scenario.DEPLETED, 1, o);
        assertTrue(depleted.truth().faulty() && verdict(depleted, PropertyJudge.BATTERY).violated());
    }

    @Test
    void aGraspThatKeepsFailingUsesUpItsAttemptsAtTheKthFailure() throws IOException {
        SimOptions o = with(Novelties.NONE.withGrasp(true, new Span(20, 40)));
        for (Scenario s : List.of(Scenario.DIRECT, Scenario.RECHARGE)) {
            for (long seed = 1; seed <= 4; seed++) {
                SimRun run = Simulator.run(s, seed, o);
                String id = s.id() + " seed " + seed;
                ReadBack log = ReadBack.write(dir.resolve(s.id() + seed + ".log"), o, run);
                PropertyTruth v = verdict(run, PropertyJudge.GRASP_IN_TIME);
                assertTrue(v.violated(), id);
                LogRecord failed = log.at(v.line());
                assertTrue(ReadBack.reply(failed, "hasGrasped", "0"), id + ": " + failed);
                assertEquals("/ArmServiceFetchClient", failed.to(), id + ": the fetch skill's own check");
                assertEquals(K, log.before(v.line()).stream().filter(r -> ReadBack.command(r, "closeHand", ""))
                        .count(), id + ": the K-th closeHand");
                assertEquals(v.tick(), log.tickOf(failed), id);
                long attempts = log.records().stream().filter(r -> ReadBack.command(r, "closeHand", "")).count();
                assertEquals(run.truth().novelties().graspAttempts(), (int) attempts, id);
                assertTrue(attempts >= 21 && attempts <= 41, id + ": retried dozens of times, " + attempts);
                LogRecord held = log.first(r -> ReadBack.reply(r, "hasGrasped", "1")
                        && r.to().equals("/ArmServiceFetchClient"));
                assertTrue(held.line() > v.line(), id + ": it holds in the end");
                assertFalse(verdict(run, PropertyJudge.BATTERY).violated(), id);
                assertFalse(verdict(run, PropertyJudge.NAVIGATION_IN_TIME).violated(), id);
            }
        }
    }

    @Test
    void aGraspAsTheRecordingsShowHoldsWithinItsAttempts() throws IOException {
        SimOptions o = with(Novelties.NONE.withGrasp(true, null));
        for (long seed = 1; seed <= 8; seed++) {
            SimRun run = Simulator.run(Scenario.DIRECT, seed, o);
            ReadBack log = ReadBack.write(dir.resolve("g" + seed + ".log"), o, run);
            long attempts = log.records().stream().filter(r -> ReadBack.command(r, "closeHand", "")).count();
            assertTrue(attempts >= 1 && attempts <= 4, "seed " + seed + ": " + attempts);
            assertEquals(run.truth().novelties().graspAttempts(), (int) attempts);
            String which = "seed " + seed + " ";
            run.truth().properties().forEach((id, v) -> assertFalse(v.violated(), which + id));
        }
    }

    @Test
    void aLateTurnStillHeadsElsewhereTenTicksAfterTheBatteryFellBelow30() throws IOException {
        SimOptions o = with(Novelties.NONE.withLateTurn(new Span(15, 30)));
        for (Scenario s : List.of(Scenario.RECHARGE, Scenario.DEPLETED)) {
            for (long seed = 1; seed <= 4; seed++) {
                SimRun run = Simulator.run(s, seed, o);
                String id = s.id() + " seed " + seed;
                ReadBack log = ReadBack.write(dir.resolve(s.id() + seed + ".log"), o, run);
                PropertyTruth v = verdict(run, PropertyJudge.CHARGER_IN_TIME);
                assertTrue(v.violated(), id);
                LogRecord deadline = log.at(v.line());
                assertTrue(ReadBack.tick(deadline, v.tick()), id + ": " + deadline);
                LogRecord below = log.first(r -> r.kind() == RecordKind.REPLY && r.command().equals("level")
                        && Double.parseDouble(r.reply()) < 30.0);
                assertEquals(v.tick() - PropertyLimits.DEFAULT.chargerTicks(), log.tickOf(below), id);
                assertTrue(log.before(v.line()).stream().noneMatch(r -> ReadBack.command(r, "goTo",
                        Components.CHARGING_STATION)), id + ": no goTo to the station yet");
                LogRecord turn = log.first(r -> ReadBack.command(r, "goTo", Components.CHARGING_STATION));
                int late = log.tickOf(turn) - log.tickOf(below);
                assertEquals(run.truth().novelties().lateTurnTicks(), late, id);
                assertTrue(late >= 15 && late <= 30, id + ": " + late);
                assertEquals(s.faulty(), verdict(run, PropertyJudge.BATTERY).violated(), id + ": the scenario stays");
                if (!s.faulty()) {
                    assertFalse(verdict(run, PropertyJudge.NAVIGATION_IN_TIME).violated(), id + ": only the turn is late");
                }
            }
        }
    }

    @Test
    void theTickPeriodOptionSetsTheTreesPace() throws IOException {
        SimOptions o = with(Novelties.NONE.withTickPeriod(new Span(1.0, 1.0)));
        SimRun run = Simulator.run(Scenario.RECHARGE, 3, o);
        assertEquals(1.0, run.truth().parameters().tickPeriod());
        ReadBack log = ReadBack.write(dir.resolve("t.log"), o, run);
        List<LogRecord> ticks = log.records().stream().filter(r -> r.kind() == RecordKind.TICK).toList();
        for (int i = 1; i < ticks.size(); i++) {
            assertEquals(1.0, ticks.get(i).time() - ticks.get(i - 1).time(), 0.0011, "tick " + i);
        }
        double drawn = Simulator.run(Scenario.DIRECT, 3, with(Novelties.NONE.withTickPeriod(new Span(0.8, 1.2))))
                .truth().parameters().tickPeriod();
        assertTrue(drawn >= 0.8 && drawn < 1.2, "drawn " + drawn);
    }

    @Test
    void theCommandLineTakesTheNewNoveltiesAndTheLimitsAndRefusesAWrongValue() throws IOException {
        Path file = dir.resolve("stuck.log");
        StringWriter err = new StringWriter();
        CommandLine cl = new CommandLine(new SimulateCommand());
        cl.setErr(new PrintWriter(err, true));
        assertEquals(0, cl.execute("--scenario", "direct", "--seed", "2", "--never-arrives", "120",
                "--navigation-deadline", "100", "--out", file.toString()), err.toString());
        JsonNode navigation = new ObjectMapper().readTree(TruthWriter.sidecarOf(file).toFile()).get("properties")
                .get(PropertyJudge.NAVIGATION_IN_TIME);
        assertTrue(navigation.get("violated").asBoolean(), navigation.toString());
        ReadBack log = ReadBack.read(file);
        LogRecord goTo = log.first(r -> ReadBack.command(r, "goTo", "kitchen"));
        assertEquals(log.tickOf(goTo) + 100, navigation.get("tick").asInt(), "the deadline given, not the default");
        assertTrue(ReadBack.tick(log.at(navigation.get("line").asLong()), navigation.get("tick").asInt()));
        CommandLine bad = new CommandLine(new SimulateCommand());
        StringWriter badErr = new StringWriter();
        bad.setErr(new PrintWriter(badErr, true));
        assertEquals(2, bad.execute("--scenario", "direct", "--grasp-failures", "many", "--out",
                dir.resolve("x.log").toString()));
        assertTrue(badErr.toString().contains("--grasp-failures: expected a number or a range"), badErr.toString());
        assertFalse(Files.exists(dir.resolve("x.log")), "nothing written");
    }
}
