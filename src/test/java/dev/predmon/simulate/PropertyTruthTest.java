package dev.predmon.simulate;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.cli.SimulateCommand;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.simulate.Novelties.AbortOn;
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
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The truth's {@code properties}: a training set of default runs violates none of the new properties (only what an
 * empty battery makes happen), and each violation the truth claims is at a line of the written log where the
 * project's own parser finds the record that shows it, in every layout and in a log of several runs.
 */
class PropertyTruthTest {

    private static final List<String> NEW = List.of(PropertyJudge.CHARGER_IN_TIME, PropertyJudge.NO_ABORT,
            PropertyJudge.NAVIGATION_IN_TIME, PropertyJudge.GRASP_IN_TIME);

    @TempDir
    Path dir;

    private static PropertyTruth verdict(SimRun run, String id) {
        return run.truth().properties().get(id);
    }

    @Test
    void aTrainingSetOfDefaultRunsViolatesNoNewPropertyButWhatAnEmptyBatteryMakesHappen() {
        for (Scenario s : List.of(Scenario.DIRECT, Scenario.RECHARGE)) {
            for (SimRun run : Runs.of(s)) {
                assertEquals(PropertyJudge.IDS, List.copyOf(run.truth().properties().keySet()));
                run.truth().properties().forEach((id, v) -> assertFalse(v.violated(),
                        s.id() + " seed " + run.seed() + " violates " + id + " at line " + v.line()));
            }
        }
        int navigations = 0;
        for (SimRun run : Runs.of(Scenario.DEPLETED)) {
            String id = "depleted seed " + run.seed();
            PropertyTruth battery = verdict(run, PropertyJudge.BATTERY);
            assertTrue(battery.violated(), id);
            assertEquals(run.truth().violationTime(), battery.time(), id);
            assertFalse(verdict(run, PropertyJudge.CHARGER_IN_TIME).violated(), id + ": turns at the early warning");
            assertFalse(verdict(run, PropertyJudge.GRASP_IN_TIME).violated(), id + ": grasps nothing");
            // The navigation aborts when the battery is empty, long after the level fell below 20.
            assertTrue(verdict(run, PropertyJudge.NO_ABORT).time() > battery.time(), id);
            PropertyTruth navigation = verdict(run, PropertyJudge.NAVIGATION_IN_TIME);
            if (navigation.violated()) {
                // A long way, to a station too far or to the kitchen before the turn: the deadline of 300 ticks is
                // above every navigation of the nominal default runs here, not above every one a depleted run makes.
                navigations++;
            }
        }
        assertTrue(navigations <= Runs.SEEDS / 20, navigations + " depleted runs out of time on a navigation");
    }

    @Test
    void theBatteryViolationIsTheFirstLevelReadingBelow20InTheWrittenLog() throws IOException {
        for (long seed = 1; seed <= 5; seed++) {
            SimRun run = Runs.of(Scenario.DEPLETED).get((int) seed - 1);
            ReadBack log = ReadBack.write(dir.resolve("d" + seed + ".log"), run.options(), run);
            PropertyTruth v = verdict(run, PropertyJudge.BATTERY);
            LogRecord r = log.at(v.line());
            assertEquals("level", r.command());
            assertEquals(RecordKind.REPLY, r.kind());
            assertTrue(Double.parseDouble(r.reply()) < 20.0);
            assertEquals(r, log.first(x -> x.kind() == RecordKind.REPLY && x.command().equals("level")
                    && Double.parseDouble(x.reply()) < 20.0));
            assertEquals(v.tick(), log.tickOf(r));
            assertEquals(v.time(), r.time());
        }
    }

    @Test
    void anAbortedNavigationViolatesNoAbortAtItsReplyAndTheRunKeepsItsBattery() throws IOException {
        SimOptions o = SimOptions.defaults().withNovelties(Novelties.NONE.withAborts(1, AbortOn.ANY));
        for (Scenario s : List.of(Scenario.DIRECT, Scenario.RECHARGE)) {
            for (long seed = 1; seed <= 4; seed++) {
                SimRun run = Simulator.run(s, seed, o);
                String id = s.id() + " seed " + seed;
                ReadBack log = ReadBack.write(dir.resolve(s.id() + seed + ".log"), o, run);
                PropertyTruth v = verdict(run, PropertyJudge.NO_ABORT);
                assertTrue(v.violated(), id);
                LogRecord abort = log.at(v.line());
                assertTrue(ReadBack.reply(abort, "getStatus", "3"), id + ": " + abort);
                assertEquals(abort, log.first(r -> ReadBack.reply(r, "getStatus", "3")), id + ": the first ABORT");
                assertEquals(run.truth().novelties().aborts().get(0).abortTime(), abort.time(), id);
                assertEquals(v.tick(), log.tickOf(abort), id);
                assertFalse(verdict(run, PropertyJudge.BATTERY).violated(), id);
                assertFalse(verdict(run, PropertyJudge.GRASP_IN_TIME).violated(), id);
            }
        }
    }

    @Test
    void linesHoldWithRawLinesLateRepliesAndNoTicksAndInALogOfSeveralRuns() throws IOException {
        Path file = dir.resolve("day.log");
        StringWriter err = new StringWriter();
        CommandLine cl = new CommandLine(new SimulateCommand());
        cl.setErr(new PrintWriter(err, true));
        assertEquals(0, cl.execute("--scenario", "depleted,recharge,depleted", "--seed", "40", "--runs-per-log", "3",
                "--raw-lines", "--late-replies", "0.3", "--no-ticks", "--aborts", "1", "--abort-on", "station",
                "--out", file.toString()), err.toString());
        JsonNode truths = new ObjectMapper().readTree(TruthWriter.sidecarOf(file).toFile());
        ReadBack log = ReadBack.read(file);
        assertEquals(3, truths.size());
        long previous = 0;
        for (JsonNode truth : truths) {
            JsonNode properties = truth.get("properties");
            for (String id : NEW) {
                assertTrue(properties.has(id), id);
            }
            JsonNode abort = properties.get(PropertyJudge.NO_ABORT);
            assertTrue(abort.get("violated").asBoolean());
            LogRecord r = log.at(abort.get("line").asLong());
            assertTrue(ReadBack.reply(r, "getStatus", "3"), r.toString());
            assertEquals(truth.get("novelties").get("aborts").get(0).get("abortTime").asDouble(), r.time());
            assertTrue(r.line() > previous, "each run's lines lie after the previous run's");
            previous = r.line();
            JsonNode battery = properties.get(PropertyJudge.BATTERY);
            if (truth.get("faulty").asBoolean()) {
                LogRecord low = log.at(battery.get("line").asLong());
                assertEquals("level", low.command());
                assertEquals(truth.get("violationTime").asDouble(), low.time());
            } else {
                assertEquals(1, battery.size(), "a property that held says only so: " + battery);
            }
        }
        assertTrue(Files.readString(file).contains("INFO"), "raw lines are printed");
    }
}
