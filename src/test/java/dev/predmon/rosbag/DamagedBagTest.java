package dev.predmon.rosbag;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Damaged recordings give one problem line each, naming the file, the record and what was expected, with every
 * message before it delivered, and never hang: cut at every byte, a bad CRC, a chunk cut mid-write, an unknown
 * type, another encoding, an impossible length.
 */
class DamagedBagTest {

    @TempDir
    Path dir;

    /** 12 messages on two topics in 3 chunks of 4. */
    static byte[] bag(McapWriter.Compression compression) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (McapWriter w = new McapWriter(out, compression, 1 << 20)) {
            int chatter = w.channel("/chatter", "std_msgs/msg/String");
            int clock = w.channel("/clock", "builtin_interfaces/msg/Time");
            for (int i = 0; i < 6; i++) {
                w.write(chatter, 1000 + 2 * i, Map.of("data", "message " + i));
                w.write(clock, 1001 + 2 * i, Map.of("sec", i, "nanosec", 2 * i));
                if (i % 2 == 1) {
                    w.flush();
                }
            }
        }
        return out.toByteArray();
    }

    private Collected read(byte[] bytes) throws IOException {
        Path f = dir.resolve("bag.mcap");
        Files.write(f, bytes);
        return Collected.read(f);
    }

    private static void assertPrefix(List<BagMessage> all, List<BagMessage> some, String what) {
        assertTrue(some.size() <= all.size(), what);
        assertEquals(all.subList(0, some.size()), some, what);
    }

    @Test
    void cutAtEveryByteGivesOneProblemAndKeepsEveryMessageBefore() {
        assertTimeoutPreemptively(Duration.ofMinutes(2), () -> {
            for (McapWriter.Compression c : McapWriter.Compression.values()) {
                byte[] full = bag(c);
                List<BagMessage> all = read(full).messages;
                assertEquals(12, all.size());
                int closed = full.length - 8 - 29; // after DataEnd: the footer and magic add nothing to the data
                int step = c == McapWriter.Compression.NONE ? 1 : 5; // the compressed forms: fewer cuts, same code
                for (int n = 0; n < full.length; n += step) {
                    Collected got = read(Arrays.copyOf(full, n));
                    String what = c + " cut at " + n + " of " + full.length + ": " + got.problems;
                    assertEquals(n < closed ? 1 : 0, got.problems.size(), what);
                    assertPrefix(all, got.messages, what);
                    if (n < closed) {
                        assertTrue(got.problems.get(0).startsWith(dir.resolve("bag.mcap") + ": "), what);
                    } else {
                        assertEquals(12, got.messages.size(), what);
                    }
                }
            }
        });
    }

    @Test
    void aBadCrcIsOneProblemAfterTheChunksBefore() throws IOException {
        for (McapWriter.Compression c : McapWriter.Compression.values()) {
            byte[] bytes = bag(c);
            long[] second = RawMcap.records(bytes).stream().filter(r -> r[0] == McapScanner.CHUNK).toList().get(1);
            bytes[(int) second[1] + 9 + 24] ^= 0x01; // the CRC: after start, end and uncompressed size
            Collected got = read(bytes);
            assertEquals(1, got.problems.size(), got.problems.toString());
            assertTrue(got.problems.get(0).contains("chunk at byte " + second[1] + ": bad CRC"), got.problems.get(0));
            assertEquals(4, got.messages.size(), "the first chunk's messages are kept");
        }
    }

    @Test
    void aCorruptCompressedChunkIsOneProblem() throws IOException {
        for (McapWriter.Compression c : List.of(McapWriter.Compression.ZSTD, McapWriter.Compression.LZ4)) {
            byte[] bytes = bag(c);
            long[] second = RawMcap.records(bytes).stream().filter(r -> r[0] == McapScanner.CHUNK).toList().get(1);
            int records = (int) (second[1] + 9 + 8 + 8 + 8 + 4 + 4 + c.name().length() + 8);
            for (int i = records + 4; i < second[1] + 9 + second[2]; i++) {
                bytes[i] ^= 0x5a;
            }
            Collected got = read(bytes);
            assertEquals(1, got.problems.size(), c + ": " + got.problems);
            assertTrue(got.problems.get(0).contains("chunk at byte " + second[1]), got.problems.get(0));
            assertEquals(4, got.messages.size());
        }
    }

    @Test
    void anImpossibleRecordLengthIsOneProblem() throws IOException {
        byte[] bytes = new RawMcap().lyingRecord(McapScanner.MESSAGE, 1L << 62).end();
        Collected got = read(bytes);
        assertEquals(1, got.problems.size(), got.problems.toString());
        assertTrue(got.problems.get(0).contains("impossible length 4611686018427387904"), got.problems.get(0));
    }

    @Test
    void aSequenceOf2To31ElementsIsOneProblemAndTheTopicIsSkippedTheOthersGoOn() throws IOException {
        byte[] huge = {0, 1, 0, 0, 0, 0, 0, (byte) 0x80}; // GoalStatusArray with 2^31 statuses, then nothing
        byte[] bytes = new RawMcap()
                .schema(1, "action_msgs/msg/GoalStatusArray", "ros2msg", BundledTypes.text("action_msgs/msg/GoalStatusArray"))
                .schema(2, "sensor_msgs/msg/BatteryState", "ros2msg", BundledTypes.text("sensor_msgs/msg/BatteryState"))
                .channel(1, 1, "/status", "cdr").channel(2, 2, "/battery_state", "cdr")
                .message(2, 10, RawMcap.battery(0.5)).message(1, 11, huge).message(1, 12, huge)
                .message(2, 13, RawMcap.battery(0.25)).end();
        Collected got = read(bytes);
        assertEquals(1, got.problems.size(), got.problems.toString());
        assertTrue(got.problems.get(0).contains("impossible length 2147483648 of sequence status_list"),
                got.problems.get(0));
        assertTrue(got.problems.get(0).contains("message 2 of topic /status"), got.problems.get(0));
        assertEquals(List.of(10L, 13L), got.messages.stream().map(BagMessage::logTimeNanos).toList());

        Path db3 = dir.resolve("huge.db3");
        try (Db3Writer w = new Db3Writer(db3, false)) {
            int b = w.topic("/battery_state", "sensor_msgs/msg/BatteryState");
            int s = w.topic("/status", "action_msgs/msg/GoalStatusArray");
            w.write(b, 10, RawMcap.battery(0.5));
            w.write(s, 11, huge);
        }
        Collected fromDb3 = Collected.read(db3);
        assertEquals(1, fromDb3.problems.size(), fromDb3.problems.toString());
        assertTrue(fromDb3.problems.get(0).startsWith(db3 + ": row id 2 of the table messages: "),
                fromDb3.problems.get(0));
        assertEquals(1, fromDb3.messages.size());
    }

    @Test
    void anUnknownTypeIsOneProblemUnlessItsTopicIsNotWanted() throws IOException {
        byte[] bytes = new RawMcap()
                .schema(1, "acme_msgs/msg/Widget", "ros2msg", "")
                .schema(2, "sensor_msgs/msg/BatteryState", "ros2msg", BundledTypes.text("sensor_msgs/msg/BatteryState"))
                .channel(1, 1, "/widget", "cdr").channel(2, 2, "/battery_state", "cdr")
                .message(2, 10, RawMcap.battery(0.5)).message(1, 11, new byte[] {0, 1, 0, 0})
                .message(1, 12, new byte[] {0, 1, 0, 0}).message(2, 13, RawMcap.battery(0.25)).end();
        Collected got = read(bytes);
        assertEquals(List.of(dir.resolve("bag.mcap") + ": record at byte " + RawMcap.records(bytes).get(6)[1]
                + ": cannot decode topic /widget (acme_msgs/msg/Widget): the recording carries no definition of "
                + "acme_msgs/msg/Widget, and predmon has none bundled (no definition of acme_msgs/msg/Widget); its "
                + "messages are skipped"), got.problems);
        assertEquals(2, got.messages.size());

        Collected batteryOnly = new Collected() {
            @Override
            public boolean wants(String topic, String type) {
                return topic.equals("/battery_state");
            }
        };
        Path f = dir.resolve("bag.mcap");
        Bags.read(f, batteryOnly);
        assertEquals(List.of(), batteryOnly.problems);
        assertEquals(2, batteryOnly.messages.size());
    }

    @Test
    void anotherMessageEncodingIsOneProblem() throws IOException {
        byte[] bytes = new RawMcap()
                .schema(1, "sensor_msgs/msg/BatteryState", "ros2msg", BundledTypes.text("sensor_msgs/msg/BatteryState"))
                .channel(1, 1, "/battery_state", "json").message(1, 10, "{}".getBytes(java.nio.charset.StandardCharsets.UTF_8))
                .message(1, 11, "{}".getBytes(java.nio.charset.StandardCharsets.UTF_8)).end();
        Collected got = read(bytes);
        assertEquals(1, got.problems.size(), got.problems.toString());
        assertTrue(got.problems.get(0).contains("has the message encoding 'json', expected cdr"), got.problems.get(0));
    }

    @Test
    void aBundledTypeNeedsNoDefinitionAndIdlFallsBackToIt() throws IOException {
        byte[] bytes = new RawMcap()
                .schema(1, "sensor_msgs/msg/BatteryState", "ros2idl", "module sensor_msgs { ... };")
                .channel(1, 1, "/battery_state", "cdr").channel(2, 0, "/battery2", "cdr")
                .message(1, 10, RawMcap.battery(0.5)).end();
        Collected got = read(bytes);
        assertEquals(List.of(), got.problems);
        assertEquals(0.5, (Double) got.messages.get(0).fields().get("percentage"), 0.0);
    }

    @Test
    void aFileThatIsNoBagIsOneProblem() throws IOException {
        Collected got = read("2024-01-01 12:00:00 intercepted something\n".getBytes(java.nio.charset.StandardCharsets.UTF_8));
        assertEquals(1, got.problems.size());
        assertTrue(got.problems.get(0).contains("expected an MCAP file"), got.problems.get(0));
        Files.writeString(dir.resolve("not.db3"), "SQLite format 3\0 but not really a database at all........");
        Collected db = Collected.read(dir.resolve("not.db3"));
        assertEquals(1, db.problems.size(), db.problems.toString());
    }
}
