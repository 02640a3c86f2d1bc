package dev.predmon.simulate;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogFormat;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;
import dev.predmon.property.PropertyChecker;
import dev.predmon.ros2.TopicMapping;
import dev.predmon.rosbag.BagMessage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A simulated run as the YARP monitor logs it (read with {@code thesis}) and as nav2 records it (mapped by
 * {@code nav2}): the properties both abstractions have, {@code battery} and {@code no-abort}, are violated on the
 * same runs, at the same time. The deadlines are not compared: {@code thesis} counts ticks, a bag has none.
 */
class Nav2RecordingTest {

    private static final Abstraction THESIS = AbstractionFiles.defaults();
    private static final Abstraction NAV2 = AbstractionFiles.builtin("nav2").orElseThrow();

    @TempDir
    Path dir;

    /** Each property's first violation, by id, as {@code time} (or {@code holds}). */
    private static Map<String, String> verdicts(Abstraction a, List<LogRecord> records) {
        Map<String, String> first = new TreeMap<>();
        a.properties().forEach(p -> first.put(p.id(), "holds"));
        PropertyChecker checker = new PropertyChecker(a.properties(), (i, p, v) -> first.putIfAbsent(p.id() + "@",
                String.format("%.6f", v.time())));
        records.forEach(checker::accept);
        Map<String, String> out = new TreeMap<>();
        for (String id : List.of("battery", "no-abort")) {
            out.put(id, first.getOrDefault(id + "@", "holds"));
        }
        return out;
    }

    private List<LogRecord> yarp(SimRun run) throws IOException {
        Path log = dir.resolve(run.scenario().id() + "-" + run.seed() + ".log");
        Files.writeString(log, LogWriter.toText(run, run.options()));
        List<LogRecord> records = new ArrayList<>();
        try (RecordSource s = LogFormat.yarp().read(log, RecordSink.of(records::add, p -> { }))) {
            s.drain();
        }
        return records;
    }

    private static List<LogRecord> bag(SimRun run) {
        List<LogRecord> records = new ArrayList<>();
        TopicMapping mapping = new TopicMapping(NAV2.topicRules());
        for (BagMessage m : Nav2Recording.of(run)) {
            mapping.map(m, records::add);
        }
        return records;
    }

    @Test
    void batteryAndAbortVerdictsAreTheSameAsTheYarpLogsAtTheSameTimes() throws IOException {
        SimOptions aborting = SimOptions.defaults().withNovelties(Novelties.NONE.withAborts(1, Novelties.AbortOn.ANY));
        int violated = 0;
        int aborted = 0;
        for (Scenario s : Scenario.values()) {
            for (long seed = 1; seed <= 6; seed++) {
                for (SimOptions o : List.of(SimOptions.defaults(), aborting)) {
                    SimRun run = Simulator.run(s, seed, o);
                    Map<String, String> expected = verdicts(THESIS, yarp(run));
                    assertEquals(expected, verdicts(NAV2, bag(run)), s.id() + " seed " + seed);
                    violated += expected.get("battery").equals("holds") ? 0 : 1;
                    aborted += expected.get("no-abort").equals("holds") ? 0 : 1;
                }
            }
        }
        assertEquals(12, violated, "every depleted run violates the battery property, no other does");
        assertTrue(aborted >= 10, "most runs with an abort violate no-abort: " + aborted);
    }

    @Test
    void theStatusArrayRepeatsGoalsAndTheMappingGivesEachTransitionOnce() {
        SimRun run = Simulator.run(Scenario.RECHARGE, 3, SimOptions.defaults());
        List<BagMessage> messages = Nav2Recording.of(run);
        long arrays = messages.stream().filter(m -> m.topic().equals(Nav2Recording.NAVIGATE)).count();
        List<String> goals = bag(run).stream().filter(r -> r.kind() == dev.predmon.parse.RecordKind.REPLY
                && !r.protocol().equals("battery")).map(r -> r.protocol() + ":" + r.reply()).toList();
        assertTrue(arrays > 10, "the navigation status is published at every poll: " + arrays);
        // to the kitchen; to the dock, the kitchen's halted on the way; at the dock; to the kitchen again and there
        assertEquals(List.of("navigate_to_pose:executing", "dock_robot:executing", "navigate_to_pose:canceled",
                "dock_robot:succeeded", "navigate_to_pose:executing", "navigate_to_pose:succeeded"), goals);
    }
}
