package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.McapWriter;
import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.BufferedOutputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code watch} (the command, as a user runs it) on a rosbag2 folder that a recorder is still writing, as
 * {@code ros2 bag record} does: MCAP chunks appended to {@code run_0.mcap}, which is then closed at its size limit
 * and the recording goes on in {@code run_1.mcap}. The battery's warning comes from one message of the second file;
 * the recorder writes the chunk holding it and then writes nothing more until {@code watch} has printed the warning:
 * so the warning is printed within one chunk of its message (not at the end of the file, nor a chunk later), for the
 * message a complete recording warns at, with the same forecast.
 */
class WatchGrowingBagTest {

    private static final int CHUNK = 8;

    @TempDir
    Path dir;

    private static List<JsonNode> events(String out) throws Exception {
        return new Cli(0, out, "").jsonLines();
    }

    private static JsonNode first(List<JsonNode> events, String kind) {
        return Cli.firstEvent(events, kind).orElse(null);
    }

    /** Appends messages [from, to) to {@code w} in chunks of {@link #CHUNK}, each flushed to the file. */
    private static void chunks(McapWriter w, Map<String, Integer> channels, List<BagMessage> messages, int from,
                               int to) throws Exception {
        for (int i = from; i < to; i++) {
            BagMessage m = messages.get(i);
            int c = channels.computeIfAbsent(m.topic(), t -> w.channel(t, m.type()));
            w.write(c, m.logTimeNanos(), m.fields());
            if ((i + 1 - from) % CHUNK == 0 || i == to - 1) {
                w.flush();
            }
        }
    }

    @Test
    void theWarningComesWithinOneChunkOfItsMessageAcrossASplit() throws Exception {
        Path models = Nav2Runs.models();
        List<BagMessage> messages = Nav2Runs.messages(Scenario.DEPLETED, 4242);
        // Where a complete recording warns: the message, counted from 1.
        Path whole = dir.resolve("whole.mcap");
        Nav2Runs.write(whole, messages);
        Cli once = Cli.run("watch", "--log", whole.toString(), "--models", models.toString(), "--no-follow", "--json");
        JsonNode expected = first(once.jsonLines(), "warning");
        assertTrue(expected != null, "a depleted run is warned: " + once.out());
        int warningMessage = expected.get("line").asInt();
        int split = warningMessage - 3 * CHUNK - 5; // the first file ends three chunks and a bit before it
        assertTrue(split > CHUNK, "room for a first file: " + warningMessage);
        // In the second file its index counts from that file's start; its chunk is the one that reaches it.
        int inSecond = warningMessage - split;
        int chunkEnd = split + ((inSecond + CHUNK - 1) / CHUNK) * CHUNK;

        Path run = Files.createDirectories(dir.resolve("live").resolve("run"));
        Map<String, Integer> channels = new HashMap<>();
        Cli.Running watch = null;
        try {
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(run.resolve("run_0.mcap")));
                 McapWriter w = new McapWriter(out, McapWriter.Compression.ZSTD, 1 << 20)) {
                chunks(w, channels, messages, 0, CHUNK);
                watch = Cli.start("watch", "--log", run.toString(), "--models", models.toString(), "--json",
                        "--poll-ms", "5");
                chunks(w, channels, messages, CHUNK, split);
            } // closed at its size limit: end records written
            channels.clear();
            Cli.Running live = watch;
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(run.resolve("run_1.mcap")));
                 McapWriter w = new McapWriter(out, McapWriter.Compression.LZ4, 1 << 20)) {
                chunks(w, channels, messages, split, chunkEnd - CHUNK);
                Thread.sleep(300); // time enough to warn too early, were it to
                assertEquals(null, first(events(live.out().toString()), "warning"),
                        "no warning before the chunk of its message");
                chunks(w, channels, messages, chunkEnd - CHUNK, chunkEnd);
                FleetWatchTest.await(() -> live.out().toString().contains("\"event\":\"warning\""),
                        "the warning, with nothing written after the chunk of its message");
                JsonNode warning = first(events(live.out().toString()), "warning");
                assertEquals(inSecond, warning.get("line").asInt(), "the message that warns, in run_1.mcap");
                assertEquals(expected.get("time").asDouble(), warning.get("time").asDouble(), warning.toString());
                assertEquals(expected.get("reason").asText(), warning.get("reason").asText());
                chunks(w, channels, messages, chunkEnd, messages.size());
            }
            FleetWatchTest.await(() -> live.out().toString().contains("\"event\":\"violation\""),
                    "the violation after it");
            assertEquals(first(once.jsonLines(), "violation").get("time").asDouble(),
                    first(events(live.out().toString()), "violation").get("time").asDouble());
            assertEquals(-1, live.code().get(), "still watching: " + live.err());
        } finally {
            if (watch != null) {
                watch.stop();
            }
        }
    }
}
