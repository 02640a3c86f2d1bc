package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogRecord;
import dev.predmon.ros2.TopicMapping;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.PythonBags;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Nav2Recording;
import dev.predmon.simulate.Novelties;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimEvent;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The same simulated runs in every form a ROS 2 robot's recording takes, written by writers that are not predmon's
 * ({@code rosbags}: a sqlite3 and an MCAP rosbag2 folder; {@code mcap-ros2-support}: zstd and lz4 MCAP files), and
 * watched ({@code watch --no-follow --json}) with the same {@code nav2} models, give the same stream of events:
 * every forecast (of the battery and of the deadlines), elimination, warning, violation and the end summary, each
 * field, in order. Only {@code wallTime}, when the event was printed, is left out.
 *
 * <p>The YARP log of the same runs gives that stream too. Here the YARP log is the one a YARP monitor prints of the
 * calls that the bags carry: each call the {@code nav2} mapping reads from a message (a battery reading, a goal's
 * change of status) printed as the monitor prints any call, a command record and its reply record. (The simulator's
 * own YARP log speaks of another interface, the battery component's {@code level} and the navigation's {@code goTo}
 * polled by {@code getStatus} at every tick, which the {@code thesis} abstraction maps to another alphabet with other
 * models; its forecasts are other numbers by construction. Its verdicts are not: {@link
 * #theSimulatorsYarpLogViolatesAtTheSameTimes} checks them.) One thing must differ: the numbering. A bag's record
 * is numbered by the index of the message it came from, and a message that maps to nothing (a status array
 * repeated with no change) still takes an index; a YARP log's record by the line its record starts at, seven lines
 * a record. The test turns each YARP line back into the index of the message its call came from, then requires
 * the streams to be equal, numbers included; the end event's count of records is the same. The exit code is
 * compared too.
 */
class BagFormsAgreeTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final List<String> FORMS = List.of("rosbags_sqlite3", "rosbags_mcap", "zstd", "lz4");
    /** The fields of an event that number a record. */
    private static final Set<String> NUMBERS = Set.of("line", "warnedAt", "novelSince");
    private static final Pattern LINE = Pattern.compile("\\bline (\\d+)");

    @TempDir
    static Path dir;
    private static final Map<String, SimRun> RUNS = new LinkedHashMap<>();

    @BeforeAll
    static void write() throws Exception {
        PythonBags.python(); // skips the class, with a message, where the writers are not installed
        SimOptions aborting = SimOptions.defaults().withNovelties(Novelties.NONE.withAborts(1, Novelties.AbortOn.ANY));
        for (Scenario s : Scenario.values()) {
            RUNS.put(s.id() + "-301", Simulator.run(s, 301, SimOptions.defaults()));
            RUNS.put(s.id() + "-302", Simulator.run(s, 302, SimOptions.defaults()));
            RUNS.put(s.id() + "-303-abort", Simulator.run(s, 303, aborting));
        }
        Path in = Files.createDirectories(dir.resolve("in"));
        for (Map.Entry<String, SimRun> e : RUNS.entrySet()) {
            List<Map<String, Object>> messages = new ArrayList<>();
            for (BagMessage m : Nav2Recording.of(e.getValue())) {
                messages.add(Map.of("topic", m.topic(), "type", m.type(), "log_time", m.logTimeNanos(),
                        "fields", m.fields()));
            }
            JSON.writeValue(in.resolve(e.getKey() + ".messages.json").toFile(), messages);
        }
        assertEquals(String.valueOf(RUNS.size() * FORMS.size()),
                PythonBags.run("write_runs.py", in.toString(), dir.toString()).strip());
    }

    private static Path form(String form, String run) {
        return dir.resolve(form).resolve(form.startsWith("rosbags_") ? run : run + ".mcap");
    }

    private static List<JsonNode> watch(Path log, Path models) throws IOException {
        Cli r = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow", "--json");
        assertTrue(Set.of(ExitCodes.USAGE, ExitCodes.BAD_INPUT, ExitCodes.INTERNAL).stream()
                .noneMatch(c -> c == r.code()), log + ": " + r.err());
        List<JsonNode> events = r.jsonLines();
        assertEquals("end", events.get(events.size() - 1).get("event").asText(), log + ": " + r.out());
        // The exit code, which says warned, violated unwarned or matched no model, last: compared with the events.
        events.add(JSON.createObjectNode().put("event", "exit").put("code", r.code()));
        return events;
    }

    /**
     * {@code events} without their wall time, each record number through {@code number} (null: as they are), one
     * event a line.
     */
    private static String comparable(List<JsonNode> events, Map<Long, Long> number) {
        StringBuilder out = new StringBuilder();
        for (JsonNode e : events) {
            JsonNode copy = e.deepCopy();
            strip(copy, number);
            out.append(copy).append('\n');
        }
        return out.toString();
    }

    private static void strip(JsonNode node, Map<Long, Long> number) {
        if (node instanceof ObjectNode o) {
            o.remove("wallTime");
            for (String name : NUMBERS) {
                JsonNode n = o.get(name);
                if (number != null && n != null && n.isIntegralNumber()) {
                    Long to = number.get(n.asLong());
                    assertTrue(to != null, name + " " + n + " is the line of no record of the YARP log");
                    o.put(name, to);
                }
            }
            if (number != null) {
                // words that name a record's line ("novel behaviour since line 68") name it by the message too
                for (Map.Entry<String, JsonNode> f : List.copyOf(o.properties())) {
                    if (f.getValue().isTextual()) {
                        o.put(f.getKey(), LINE.matcher(f.getValue().asText()).replaceAll(m -> "line "
                                + number.getOrDefault(Long.parseLong(m.group(1)), -1L)));
                    }
                }
            }
        }
        node.forEach(child -> strip(child, number));
    }

    @Test
    void everyFormGivesTheSameEventsAsTheYarpLogOfTheSameCalls() throws IOException {
        Path models = Nav2Runs.models();
        TopicMapping mapping = new TopicMapping(AbstractionFiles.builtin("nav2").orElseThrow().topicRules());
        int warned = 0;
        int violated = 0;
        for (Map.Entry<String, SimRun> e : RUNS.entrySet()) {
            String run = e.getKey();
            List<BagMessage> messages = Nav2Recording.of(e.getValue());
            // The YARP log of the same calls, and which message each of its records' lines came from.
            List<LogRecord> records = new ArrayList<>();
            mapping.reset();
            messages.forEach(m -> mapping.map(m, records::add));
            StringBuilder text = new StringBuilder();
            Map<Long, Long> messageOf = new LinkedHashMap<>();
            for (int i = 0; i < records.size(); i++) {
                LogRecord r = records.get(i);
                messageOf.put(7L * i + 1, r.line());
                LogWriter.format(new SimEvent(Math.round(r.time() * 1e6), r.kind(), r.from(), r.to(), r.protocol(),
                        r.command(), r.arguments(), r.reply()), SimOptions.defaults(), text);
            }
            Path yarp = dir.resolve(run + ".log");
            Files.writeString(yarp, text);

            List<JsonNode> first = watch(form(FORMS.get(0), run), models);
            JsonNode end = first.get(first.size() - 2);
            assertEquals(records.size(), end.get("records").asLong(), run + ": the records of the bag's calls");
            String expected = comparable(first, null);
            for (String f : FORMS.subList(1, FORMS.size())) {
                assertEquals(expected, comparable(watch(form(f, run), models), null), run + " as " + f);
            }
            assertEquals(expected, comparable(watch(yarp, models), messageOf), run + ": the YARP log of the calls");

            warned += first.stream().anyMatch(x -> x.get("event").asText().equals("warning")) ? 1 : 0;
            violated += first.stream().anyMatch(x -> x.get("event").asText().equals("violation")) ? 1 : 0;
            assertTrue(first.stream().filter(x -> x.get("event").asText().equals("forecast")).count() > 3, run);
        }
        // Not an agreement on nothing: the runs hold warnings and violations (the depleted runs and the aborts).
        assertTrue(warned >= 3 && violated >= 5, "warned " + warned + ", violated " + violated);
    }

    /** Each violation event's property and time, in order. */
    private static List<String> violations(List<JsonNode> events, Set<String> properties) {
        return events.stream().filter(e -> e.get("event").asText().equals("violation")
                        && properties.contains(e.get("property").asText()))
                .map(e -> e.get("property").asText() + "@" + e.get("time").asText()).toList();
    }

    /**
     * The simulator's own YARP log, watched with the shipped {@code thesis} models, and a bag of the same run written
     * by {@code rosbags}, watched with {@code nav2}: the properties both abstractions have, the battery and no abort,
     * are violated at the same times.
     */
    @Test
    void theSimulatorsYarpLogViolatesAtTheSameTimes() throws IOException {
        Path nav2 = Nav2Runs.models();
        int compared = 0;
        for (Map.Entry<String, SimRun> e : RUNS.entrySet()) {
            SimRun run = e.getValue();
            Path log = dir.resolve(e.getKey() + ".sim.log");
            Files.writeString(log, LogWriter.toText(run, run.options()));
            Set<String> both = Set.of("battery", "no-abort");
            List<String> expected = violations(watch(log, Path.of("models")), both);
            assertEquals(expected, violations(watch(form("rosbags_sqlite3", e.getKey()), nav2), both), e.getKey());
            compared += expected.size();
        }
        assertTrue(compared >= 5, "violations compared: " + compared);
    }
}
