package dev.predmon.ros2;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.rosbag.BagMessage;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The nav2 abstraction's topic rules, message by message, from messages that come from no file. */
class TopicMappingTest {

    private final Abstraction nav2 = AbstractionFiles.builtin("nav2").orElseThrow();
    private final TopicMapping mapping = new TopicMapping(nav2.topicRules());
    private final Nav2Messages m = new Nav2Messages();

    private List<LogRecord> map(BagMessage... messages) {
        List<LogRecord> out = new ArrayList<>();
        for (BagMessage message : messages) {
            mapping.map(message, out::add);
        }
        return out;
    }

    /** The replies only, as {@code protocol/command client argument=reply}; each command is the one before. */
    private static List<String> replies(List<LogRecord> records) {
        for (int i = 0; i < records.size(); i += 2) {
            LogRecord c = records.get(i);
            LogRecord r = records.get(i + 1);
            assertEquals(List.of(RecordKind.COMMAND, RecordKind.REPLY), List.of(c.kind(), r.kind()));
            assertEquals(List.of(c.from(), c.to(), c.arguments()), List.of(r.to(), r.from(), r.arguments()),
                    "a command and its reply on one connection");
        }
        return records.stream().filter(r -> r.kind() == RecordKind.REPLY)
                .map(r -> r.protocol() + "/" + r.command() + " " + r.to() + " " + r.arguments() + "=" + r.reply())
                .toList();
    }

    @Test
    void aBatteryReadingIsACallAndItsReplyAtTheMessagesIndexAndTime() {
        List<LogRecord> records = map(m.battery(1700000000.25, 0.87f));
        assertEquals(2, records.size());
        LogRecord call = records.get(0);
        LogRecord reply = records.get(1);
        assertEquals(RecordKind.COMMAND, call.kind());
        assertEquals("battery", call.protocol());
        assertEquals("percentage", call.command());
        assertEquals(RecordKind.REPLY, reply.kind());
        assertEquals(1, reply.line(), "the message's index");
        assertEquals(1700000000.25, reply.time(), 1e-6, "log time in seconds");
        // 0.87 as a float32, read as a double, times 100
        assertEquals((double) 0.87f * 100, Double.parseDouble(reply.reply()));
        assertEquals("/battery_state", reply.from());
    }

    @Test
    void theScaleIsAFractionUntilAReadingShowsPercentagesAndNanIsNoReading() {
        List<String> got = replies(map(m.battery(1, 0.5), m.battery(2, Double.NaN), m.battery(3, 96.0),
                m.battery(4, 1.0), m.battery(5, 0.5)));
        assertEquals(List.of("battery/percentage /predmon =50", "battery/percentage /predmon =96",
                "battery/percentage /predmon =1", "battery/percentage /predmon =0.5"), got, "NaN gives nothing; after 96 the topic publishes percentages");
    }

    @Test
    void aGoalStatusArrayGivesOneEventPerGoalTransitionOnly() {
        List<String> got = replies(map(
                m.navigation(1, new int[] {1, 2}),                    // goal 1 first seen executing: started
                m.navigation(2, new int[] {1, 2}),                    // repeated: nothing
                m.navigation(3, new int[] {1, 4}, new int[] {2, 1}),  // 1 succeeded, 2 accepted: started
                m.navigation(4, new int[] {1, 4}, new int[] {2, 2}),  // 2 accepted -> executing: the same word
                m.navigation(5, new int[] {1, 4}, new int[] {2, 6}),  // 2 aborted
                m.navigation(6, new int[] {2, 6})));                  // repeated: nothing
        String g1 = "00".repeat(15) + "01";
        String g2 = "00".repeat(15) + "02";
        assertEquals(List.of(
                "navigate_to_pose/goal /predmon/" + g1 + " executing=executing",
                "navigate_to_pose/goal /predmon/" + g1 + " succeeded=succeeded",
                "navigate_to_pose/goal /predmon/" + g2 + " executing=executing",
                "navigate_to_pose/goal /predmon/" + g2 + " aborted=aborted"), got);
    }

    @Test
    void theTreeLogRosoutAndDiagnosticsGiveChangesAndErrors() {
        List<String> got = replies(map(
                m.treeLog(1, "FollowPath", "IDLE", "RUNNING"),
                m.treeLog(2, "FollowPath", "RUNNING", "FAILURE"),
                m.log(3, 30, "controller_server", "a warning"),
                m.log(4, 40, "controller_server", "Failed to make progress"),
                m.log(5, 50, "bt_navigator", "fatal"),
                m.diagnostics(6, "motors", 0),
                m.diagnostics(7, "motors", 0),
                m.diagnostics(8, "motors", 2)));
        assertEquals(List.of(
                "behavior_tree/node /predmon/FollowPath RUNNING=RUNNING",
                "behavior_tree/node /predmon/FollowPath FAILURE=FAILURE",
                "rosout/log /predmon/controller_server ERROR=ERROR",
                "rosout/log /predmon/bt_navigator FATAL=FATAL",
                "diagnostics/level /predmon/motors OK=OK",
                "diagnostics/level /predmon/motors ERROR=ERROR"), got, "a WARN log and a repeated level give nothing");
    }

    @Test
    void aTopicNoRuleNamesOrATypeThatDiffersGivesNothing() {
        BagMessage other = new BagMessage(null, 1, "/cmd_vel", "geometry_msgs/msg/Twist", 0, java.util.Map.of());
        BagMessage wrongType = new BagMessage(null, 2, "/battery_state", "std_msgs/msg/Float32", 0,
                java.util.Map.of("percentage", 0.5));
        assertTrue(map(other, wrongType).isEmpty());
        assertTrue(TopicRule.sameType("sensor_msgs/BatteryState", "sensor_msgs/msg/BatteryState"));
    }

    @Test
    void fieldPathsReachNestedFieldsListElementsAndIndexedElements() {
        java.util.Map<String, Object> msg = java.util.Map.of("a", java.util.Map.of("b", 3L),
                "list", List.of(java.util.Map.of("x", 1L), java.util.Map.of("y", 2L), java.util.Map.of("x", 5L)));
        assertEquals(List.of(3L), FieldPath.parse("a.b").values(msg));
        assertEquals(java.util.Arrays.asList(1L, null, 5L), FieldPath.parse("list[].x").values(msg));
        assertEquals(List.of(5L), FieldPath.parse("list[2].x").values(msg));
        assertEquals(List.of(), FieldPath.parse("list[7].x").values(msg));
        assertEquals(List.of(), FieldPath.parse("a.c").values(msg));
    }
}
