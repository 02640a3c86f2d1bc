package dev.predmon.rosbag;

import dev.predmon.rosbag.MsgDefinitions.DefinitionException;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** CDR decoding and encoding against bytes worked out by hand. */
class CdrCodecTest {

    private static byte[] bytes(int... b) {
        byte[] out = new byte[b.length];
        for (int i = 0; i < b.length; i++) {
            out[i] = (byte) b[i];
        }
        return out;
    }

    @Test
    void aGoalStatusArrayAsRosbagsWritesIt() throws Exception {
        // 00 01 00 00 | count 1 | uuid 00..0F | sec 0x6553F100 = 1700000000 | nanosec 0 | status 2
        byte[] data = bytes(0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,
                0x00, 0xF1, 0x53, 0x65, 0, 0, 0, 0, 2);
        CdrCodec c = RawMcap.codec("action_msgs/msg/GoalStatusArray");
        Map<String, Object> m = c.decode(data, 0, data.length, null);
        Map<?, ?> status = (Map<?, ?>) ((List<?>) m.get("status_list")).get(0);
        Map<?, ?> info = (Map<?, ?>) status.get("goal_info");
        assertEquals(List.of(0L, 1L, 2L, 3L, 4L, 5L, 6L, 7L, 8L, 9L, 10L, 11L, 12L, 13L, 14L, 15L),
                ((Map<?, ?>) info.get("goal_id")).get("uuid"));
        assertEquals(Map.of("sec", 1_700_000_000L, "nanosec", 0L), info.get("stamp"));
        assertEquals(2L, status.get("status"));
        assertArrayEquals(data, c.encode(m), "encoding gives the same bytes back");
    }

    @Test
    void alignmentIsCountedAfterTheHeader() throws Exception {
        CdrCodec c = RawMcap.codec("sensor_msgs/msg/BatteryState");
        byte[] b = c.encode(Map.of("header", Map.of("frame_id", "base_link"), "voltage", 24.25));
        // after the header: sec 0..3, nanosec 4..7, length 8..11 (= 10), "base_link\0" 12..21, padding 22..23,
        // voltage 24..27
        assertEquals(10, b[4 + 8]);
        assertEquals('b', b[4 + 12]);
        assertEquals(0, b[4 + 21]);
        assertEquals(24.25f, Float.intBitsToFloat((b[4 + 24] & 0xff) | (b[4 + 25] & 0xff) << 8
                | (b[4 + 26] & 0xff) << 16 | (b[4 + 27] & 0xff) << 24));
        assertEquals(24.25, (Double) c.decode(b, 0, b.length, null).get("voltage"), 0.0);
    }

    @Test
    void bigEndianMessagesDecodeToo() throws Exception {
        Map<String, MsgDefinitions.Type> t = MsgDefinitions.parse("test_msgs/msg/Be",
                "int32 sec\nuint64 big\nstring name\nfloat64 x\n");
        CdrCodec c = CdrCodec.compile("test_msgs/msg/Be", t::get);
        // 00 00 (big-endian) | sec -2 | pad 4 | big 2^64-1 | length 2 "a\0" | pad 2 | x = 1.5 (3FF8000000000000)
        byte[] data = bytes(0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFE, 0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
                0xFF, 0, 0, 0, 2, 'a', 0, 0, 0, 0x3F, 0xF8, 0, 0, 0, 0, 0, 0);
        assertEquals(Map.of("sec", -2L, "big", -1L, "name", "a", "x", 1.5), c.decode(data, 0, data.length, null));
    }

    @Test
    void constantsDefaultsCommentsAndBoundsAreParsed() throws Exception {
        Map<String, MsgDefinitions.Type> t = MsgDefinitions.parse("test_msgs/msg/T", """
                # a comment
                int32 LIMIT=3
                string NAME = "x # y"
                int32 count 42   # a default value
                string<=4 short
                int32[<=2] few
                Other[2] two
                ================================================================================
                MSG: test_msgs/Other
                bool on
                """);
        assertEquals(List.of("count", "short", "few", "two"),
                t.get("test_msgs/msg/T").fields().stream().map(MsgDefinitions.Field::name).toList());
        assertEquals("test_msgs/msg/Other", t.get("test_msgs/msg/T").fields().get(3).type());
        CdrCodec c = CdrCodec.compile("test_msgs/msg/T", t::get);
        byte[] ok = c.encode(Map.of("count", 1, "short", "abcd", "few", List.of(1, 2)));
        assertEquals(Map.of("count", 1L, "short", "abcd", "few", List.of(1L, 2L),
                "two", List.of(Map.of("on", false), Map.of("on", false))), c.decode(ok, 0, ok.length, null));
        byte[] tooMany = c.encode(Map.of("few", List.of(1, 2, 3)));
        CdrException e = assertThrows(CdrException.class, () -> c.decode(tooMany, 0, tooMany.length, null));
        assertTrue(e.getMessage().contains("sequence few has 3 elements, more than its bound 2"), e.getMessage());
        byte[] tooLong = c.encode(Map.of("short", "abcde"));
        assertThrows(CdrException.class, () -> c.decode(tooLong, 0, tooLong.length, null));
    }

    @Test
    void aMissingTypeOrABadLineIsNamed() {
        DefinitionException e = assertThrows(DefinitionException.class, () -> CdrCodec.compile("a/msg/B",
                MsgDefinitions.parse("a/msg/B", "c/D d\n")::get));
        assertEquals("no definition of c/msg/D", e.getMessage());
        e = assertThrows(DefinitionException.class, () -> MsgDefinitions.parse("a/msg/B", "int32 x\nint32[ y\n"));
        assertTrue(e.getMessage().startsWith("line 2 of the definition of a/msg/B: expected a field type"),
                e.getMessage());
    }

    @Test
    void aHumbleBehaviorTreeLogWithoutDefinitionsDecodesWithTheOlderBundledForm() throws Exception {
        Map<String, MsgDefinitions.Type> humble = MsgDefinitions.parse("nav2_msgs/msg/BehaviorTreeLog",
                "builtin_interfaces/Time timestamp\nBehaviorTreeStatusChange[] event_log\n" + BundledText.SEPARATOR
                        + "\nMSG: nav2_msgs/BehaviorTreeStatusChange\nbuiltin_interfaces/Time timestamp\n"
                        + "string node_name\nstring previous_status\nstring current_status\n");
        CdrCodec writer = CdrCodec.compile("nav2_msgs/msg/BehaviorTreeLog",
                n -> humble.containsKey(n) ? humble.get(n) : BundledTypes.find(n, false));
        byte[] b = writer.encode(Map.of("event_log", List.of(Map.of("node_name", "FollowPath",
                "previous_status", "IDLE", "current_status", "RUNNING"))));
        TopicDecoder d = TopicDecoder.of("nav2_msgs/msg/BehaviorTreeLog", "", "");
        Map<?, ?> change = (Map<?, ?>) ((List<?>) d.decode(b, 0, b.length).get("event_log")).get(0);
        assertEquals(List.of("timestamp", "node_name", "previous_status", "current_status"), List.copyOf(change.keySet()));
        assertEquals("RUNNING", change.get("current_status"));
    }
}
