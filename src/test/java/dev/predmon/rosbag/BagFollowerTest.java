package dev.predmon.rosbag;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Following an MCAP file as it is written: whole chunks only, split files in order, a cut file reported. */
class BagFollowerTest {

    @TempDir
    Path dir;

    /** A recording of {@code chunks} chunks of 3 messages; {@code ends} receives the file length after each chunk. */
    static byte[] recording(int chunks, int first, List<Integer> ends) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        McapWriter w = new McapWriter(out, McapWriter.Compression.ZSTD, 1 << 20);
        int ch = w.channel("/chatter", "std_msgs/msg/String");
        for (int c = 0; c < chunks; c++) {
            for (int i = 0; i < 3; i++) {
                w.write(ch, first + 3L * c + i, Map.of("data", "m" + (first + 3 * c + i)));
            }
            w.flush();
            ends.add(out.size());
        }
        w.close();
        return out.toByteArray();
    }

    private static void append(Path file, byte[] bytes, int from, int to) throws IOException {
        try (OutputStream o = Files.newOutputStream(file, StandardOpenOption.CREATE, StandardOpenOption.APPEND)) {
            o.write(bytes, from, to - from);
        }
    }

    @Test
    void everyPollDeliversTheWholeChunksThereAndNeverAHalfWrittenOne() throws IOException {
        List<Integer> ends = new ArrayList<>();
        byte[] bytes = recording(4, 0, ends);
        Path file = dir.resolve("growing.mcap");
        Files.createFile(file);
        Collected got = new Collected();
        try (BagFollower f = new BagFollower(file, got)) {
            for (int n = 1; n <= bytes.length; n++) {
                append(file, bytes, n - 1, n);
                f.poll();
                int whole = 0;
                for (int end : ends) {
                    whole += n >= end ? 3 : 0;
                }
                assertEquals(whole, got.messages.size(), "after " + n + " of " + bytes.length + " bytes");
                assertEquals(List.of(), got.problems, "after " + n + " bytes");
                // ended once DataEnd is read: the Footer (29 bytes) and the magic (8) add no data
                assertEquals(n >= bytes.length - 37, f.ended(), "ended after " + n);
            }
            assertTrue(f.ended());
        }
        assertEquals(List.of("m0", "m1", "m2", "m3", "m4", "m5", "m6", "m7", "m8", "m9", "m10", "m11"),
                got.messages.stream().map(m -> m.fields().get("data")).toList());
    }

    @Test
    void splitFilesAreFollowedInOrderAndACutFileIsOneProblem() throws IOException {
        Path folder = dir.resolve("rec");
        Files.createDirectories(folder);
        List<Integer> ends0 = new ArrayList<>();
        byte[] b0 = recording(2, 0, ends0);
        byte[] b2 = recording(1, 100, new ArrayList<>());
        byte[] b10 = recording(1, 200, new ArrayList<>());
        Collected got = new Collected();
        try (BagFollower f = new BagFollower(folder, got)) {
            assertEquals(0, f.poll(), "an empty folder");
            Files.write(folder.resolve("rec_0.mcap"), Arrays.copyOf(b0, ends0.get(0) + 20)); // cut in chunk 2
            assertEquals(3, f.poll());
            assertEquals(List.of(), got.problems, "the file may still grow");
            Files.write(folder.resolve("rec_2.mcap"), b2);
            Files.write(folder.resolve("rec_10.mcap"), b10);
            assertEquals(6, f.poll());
            assertEquals(1, got.problems.size(), got.problems.toString());
            assertTrue(got.problems.get(0).startsWith(folder.resolve("rec_0.mcap") + ": "), got.problems.get(0));
            assertFalse(f.ended(), "a folder may get another file");
        }
        assertEquals(List.of("m0", "m1", "m2", "m100", "m101", "m102", "m200", "m201", "m202"),
                got.messages.stream().map(m -> m.fields().get("data")).toList());
    }

    @Test
    void splitFilesAreReadInSplitOrderAndMetadataOrderWins() throws IOException {
        Path folder = dir.resolve("rec");
        Files.createDirectories(folder);
        for (String name : List.of("rec_10.mcap", "rec_2.mcap", "rec_0.mcap")) {
            Files.write(folder.resolve(name), recording(1, Integer.parseInt(name.replaceAll("\\D", "")),
                    new ArrayList<>()));
        }
        assertEquals(List.of("rec_0.mcap", "rec_2.mcap", "rec_10.mcap"), BagFolder.contents(folder).files().stream()
                .map(p -> p.getFileName().toString()).toList());
        Metadata.write(folder, List.of("rec_2.mcap", "rec_0.mcap", "rec_10.mcap"));
        assertEquals(List.of("m2", "m3", "m4", "m0", "m1", "m2", "m10", "m11", "m12"),
                Collected.read(folder).messages.stream().map(m -> m.fields().get("data")).toList());
        Files.delete(folder.resolve("rec_0.mcap"));
        Collected missing = Collected.read(folder);
        assertEquals(1, missing.problems.size(), missing.problems.toString());
        assertTrue(missing.problems.get(0).contains("lists rec_0.mcap, which the folder does not have"));
        assertEquals(6, missing.messages.size());
    }
}
