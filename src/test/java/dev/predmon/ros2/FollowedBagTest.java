package dev.predmon.ros2;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;
import dev.predmon.property.PropertyChecker;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.McapWriter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.BufferedOutputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * An MCAP followed while a recorder appends chunks to it: each poll delivers the chunks written since the last, so the
 * battery's violation is known at the poll after the chunk holding its reading, not later; split files in order.
 */
class FollowedBagTest {

    private static final Abstraction NAV2 = AbstractionFiles.builtin("nav2").orElseThrow();

    @TempDir
    Path dir;

    private final List<LogRecord> records = new ArrayList<>();
    private final List<String> violations = new ArrayList<>();
    private final PropertyChecker checker = new PropertyChecker(NAV2.properties(),
            (i, p, v) -> violations.add(p.id() + "@" + v.line()));

    private RecordSource follow(Path path) {
        return NAV2.format().follow(path, RecordSink.of(r -> {
            records.add(r);
            checker.accept(r);
        }, p -> violations.add("problem " + p.message())));
    }

    /** One chunk of five readings, falling by one point from {@code from}. */
    private static void chunk(McapWriter w, int channel, Nav2Messages m, int from, int second) throws Exception {
        for (int k = 0; k < 5; k++) {
            BagMessage b = m.battery(second + k, (from - k) / 100.0);
            w.write(channel, b.logTimeNanos(), b.fields());
        }
        w.flush();
    }

    @Test
    void theViolationIsKnownAtThePollAfterItsChunk() throws Exception {
        Path bag = dir.resolve("robot.mcap");
        Nav2Messages m = new Nav2Messages();
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(bag));
             McapWriter w = new McapWriter(out, McapWriter.Compression.ZSTD, 1 << 20);
             RecordSource source = follow(bag)) {
            int battery = w.channel("/battery_state", Nav2Messages.BATTERY);
            source.poll();
            assertTrue(records.isEmpty());
            chunk(w, battery, m, 30, 0);   // 30..26
            assertTrue(source.poll());
            assertEquals(10, records.size(), "the whole chunk: five readings, each a call and its reply");
            chunk(w, battery, m, 25, 5);   // 25..21
            source.poll();
            assertEquals(List.of(), violations, "no reading below 20 yet");
            chunk(w, battery, m, 20, 10);  // 20, 19 (index 12): the violation, 18, 17, 16
            source.poll();
            assertEquals(List.of("battery@12"), violations, "known at the first poll after its chunk");
            assertEquals(30, records.size());
        }
    }

    @Test
    void splitFilesAreFollowedInOrder() throws Exception {
        Path folder = dir.resolve("day");
        Files.createDirectories(folder);
        Nav2Messages m = new Nav2Messages();
        try (RecordSource source = follow(folder)) {
            try (OutputStream out = Files.newOutputStream(folder.resolve("day_0.mcap"));
                 McapWriter w = new McapWriter(out, McapWriter.Compression.NONE, 1 << 20)) {
                chunk(w, w.channel("/battery_state", Nav2Messages.BATTERY), m, 90, 0);
            }
            source.poll();
            try (OutputStream out = Files.newOutputStream(folder.resolve("day_1.mcap"));
                 McapWriter w = new McapWriter(out, McapWriter.Compression.LZ4, 1 << 20)) {
                int battery = w.channel("/battery_state", Nav2Messages.BATTERY);
                chunk(w, battery, m, 85, 5);
                source.poll();
                assertEquals(20, records.size(), "the second file's first chunk, before it is closed");
                chunk(w, battery, m, 80, 10);
            }
            source.poll();
        }
        List<Double> readings = records.stream().filter(r -> r.kind() == RecordKind.REPLY)
                .map(r -> Double.parseDouble(r.reply())).toList();
        assertEquals(15, readings.size());
        for (int i = 0; i < 15; i++) {
            assertEquals(90 - i, readings.get(i), 1e-4, "in the order recorded, across the split");
        }
        assertEquals(List.of(), violations);
    }
}
