package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.PythonBags;
import dev.predmon.simulate.Nav2Recording;
import dev.predmon.simulate.Novelties;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A robot on nav2 that records only the standard topics ({@code /battery_state}, the {@code navigate_to_pose} and
 * {@code dock_robot} action status), every bag written by {@code rosbags}, not by predmon: {@code learn} and
 * {@code watch} with {@code --abstraction nav2} and nothing else. On bags never in training (new seeds of every
 * scenario, some runs with a navigation that aborts on a blocked path), {@code watch} warns of the battery before its
 * violation in at least 95% of the runs that violate it, in no run that does not, and names every abort by the
 * {@code no-abort} property at the time of the status that says it.
 *
 * <p>The truth comes from the messages written, not from predmon: a run violates the battery when some
 * {@code percentage} is below 0.2; a goal aborts when a status array first lists it ABORTED (6).
 */
class Nav2UnseenBagsTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final long ABORTED = 6;

    @TempDir
    Path dir;

    /** The truth of one unseen run. */
    private record Run(String name, Path bag, boolean violates, List<Double> aborts) {
    }

    /** Writes the run's messages for write_runs.py, and returns them. */
    private static List<BagMessage> messages(Path in, Scenario s, long seed, boolean abort) throws IOException {
        SimOptions o = abort ? SimOptions.defaults().withNovelties(Novelties.NONE.withAborts(1,
                Novelties.AbortOn.ANY)) : SimOptions.defaults();
        List<BagMessage> messages = Nav2Recording.of(Simulator.run(s, seed, o));
        List<Map<String, Object>> json = new ArrayList<>();
        for (BagMessage m : messages) {
            json.add(Map.of("topic", m.topic(), "type", m.type(), "log_time", m.logTimeNanos(), "fields", m.fields()));
        }
        Path file = in.resolve(s.id()).resolve(s.id() + "-" + seed + (abort ? "-abort" : "") + ".messages.json");
        Files.createDirectories(file.getParent());
        JSON.writeValue(file.toFile(), json);
        return messages;
    }

    private static boolean violatesBattery(List<BagMessage> messages) {
        return messages.stream().anyMatch(m -> m.topic().equals(Nav2Recording.BATTERY)
                && ((Double) m.fields().get("percentage")) < 0.2);
    }

    /** The times, in seconds, of the messages that first list a goal as aborted. */
    @SuppressWarnings("unchecked")
    private static List<Double> aborts(List<BagMessage> messages) {
        List<Double> times = new ArrayList<>();
        List<Object> seen = new ArrayList<>();
        for (BagMessage m : messages) {
            Object list = m.fields().get("status_list");
            if (list == null) {
                continue;
            }
            for (Object g : (List<Object>) list) {
                Map<String, Object> goal = (Map<String, Object>) g;
                Object id = ((Map<String, Object>) goal.get("goal_info")).get("goal_id");
                if (((Number) goal.get("status")).longValue() == ABORTED && !seen.contains(id)) {
                    seen.add(id);
                    times.add(m.logTimeNanos() / 1e9);
                }
            }
        }
        return times;
    }

    @Test
    void unseenRosbagsBagsAreWarnedAndEveryAbortIsNamed() throws Exception {
        PythonBags.python(); // skips, with a message, where the writers are not installed
        Path trainIn = dir.resolve("train-in");
        Path testIn = dir.resolve("test-in");
        for (Scenario s : Scenario.values()) {
            for (long seed = 1; seed <= 6; seed++) {
                messages(trainIn, s, seed, false);
            }
            for (long seed = 7; seed <= 8; seed++) {
                messages(trainIn, s, seed, true);
            }
        }
        List<Run> runs = new ArrayList<>();
        for (Scenario s : Scenario.values()) {
            int count = s == Scenario.DEPLETED ? 20 : 8;
            for (int k = 0; k < count; k++) {
                long seed = 1000L + k;
                boolean abort = k % 3 == 2;
                List<BagMessage> m = messages(testIn, s, seed, abort);
                String name = s.id() + "-" + seed + (abort ? "-abort" : "");
                runs.add(new Run(name, dir.resolve("test").resolve("rosbags_mcap").resolve(s.id()).resolve(name),
                        violatesBattery(m), aborts(m)));
            }
        }
        PythonBags.run("write_runs.py", trainIn.toString(), dir.resolve("train").toString(), "rosbags_sqlite3");
        PythonBags.run("write_runs.py", testIn.toString(), dir.resolve("test").toString(), "rosbags_mcap");
        Path train = dir.resolve("train").resolve("rosbags_sqlite3");
        for (Scenario s : Scenario.values()) {
            Files.writeString(train.resolve(s.id()).resolve("scenario.json"), "{\"faulty\": " + s.faulty() + "}",
                    StandardCharsets.UTF_8);
        }
        Path models = dir.resolve("models");
        Cli learn = Cli.run("learn", "--logs", train.toString(), "--models", models.toString(),
                "--abstraction", "nav2");
        assertEquals(ExitCodes.OK, learn.code(), learn.err());
        // every name the properties use is found in the bags (read as bags, not as YARP logs that hold no record)
        assertFalse(learn.err().contains("warning:"), learn.err());

        int violating = 0;
        int warnedBefore = 0;
        int falseAlarms = 0;
        int abortRuns = 0;
        List<Double> leads = new ArrayList<>();
        for (Run run : runs) {
            Cli w = Cli.run("watch", "--log", run.bag().toString(), "--models", models.toString(),
                    "--abstraction", "nav2", "--no-follow", "--json");
            assertTrue(w.code() != ExitCodes.BAD_INPUT && w.code() != ExitCodes.USAGE && w.code() != ExitCodes.INTERNAL,
                    run.name() + ": " + w.err());
            List<JsonNode> events = w.jsonLines();
            Double warning = first(events, "warning", "battery");
            Double violation = first(events, "violation", "battery");
            assertEquals(run.violates(), violation != null, run.name() + ": the battery's verdict");
            if (run.violates()) {
                violating++;
                if (warning != null && warning < violation) {
                    warnedBefore++;
                    leads.add(violation - warning);
                }
            } else if (warning != null) {
                falseAlarms++;
            }
            List<Double> named = events.stream().filter(e -> e.get("event").asText().equals("violation")
                    && e.get("property").asText().equals("no-abort")).map(e -> e.get("time").asDouble()).toList();
            if (!run.aborts().isEmpty()) {
                abortRuns++;
                assertEquals(run.aborts().subList(0, 1), named, run.name() + ": the abort named, when it happened");
            } else {
                assertEquals(List.of(), named, run.name() + ": no abort, none named");
            }
        }
        leads.sort(null);
        String figures = String.format("battery warned before its violation in %d of %d violating runs, %d false "
                        + "alarm(s) in %d runs that held, median lead %.1f s; %d run(s) with an abort, each named",
                warnedBefore, violating, falseAlarms, runs.size() - violating,
                leads.isEmpty() ? Double.NaN : leads.get(leads.size() / 2), abortRuns);
        System.out.println("Nav2UnseenBagsTest: " + figures);
        assertTrue(violating >= 15 && abortRuns >= 8, figures);
        assertTrue(warnedBefore >= 0.95 * violating, figures);
        assertEquals(0, falseAlarms, figures);
    }

    /** The time of the first event of {@code kind} for {@code property}, or null. */
    private static Double first(List<JsonNode> events, String kind, String property) {
        return events.stream().filter(e -> e.get("event").asText().equals(kind)
                && property.equals(e.path("property").asText())).map(e -> e.get("time").asDouble()).findFirst()
                .orElse(null);
    }
}
