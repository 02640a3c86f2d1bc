package dev.predmon.rosbag;

import com.fasterxml.jackson.databind.JsonNode;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * predmon's writers (MCAP with every compression, sqlite3 with and without definitions) write what the Python
 * readers and predmon's reader decode to the values given, for the messages the independent writers wrote.
 */
class OwnWriterTest {

    @TempDir
    static Path dir;
    static JsonNode expected;

    @BeforeAll
    static void write() throws Exception {
        PythonBags.run("write_bags.py", dir.toString());
        expected = JsonValues.parse(Files.readString(dir.resolve("expected.json")));
    }

    /** The definitions predmon does not bundle: the test type, from the bag rosbags wrote. */
    private static String definition(String type) throws IOException {
        if (!type.equals("predmon_test/msg/Everything")) {
            return BundledTypes.text(type);
        }
        String[] text = {null};
        try (var c = java.sql.DriverManager.getConnection("jdbc:sqlite:"
                + dir.resolve("rosbags_sqlite3").resolve("rosbags_sqlite3.db3"));
             var s = c.prepareStatement("SELECT encoded_message_definition FROM message_definitions "
                     + "WHERE topic_type = ?")) {
            s.setString(1, type);
            try (var r = s.executeQuery()) {
                r.next();
                text[0] = r.getString(1);
            }
        } catch (java.sql.SQLException e) {
            throw new IOException(e);
        }
        return text[0];
    }

    @SuppressWarnings("unchecked")
    static void writeMcap(Path file, McapWriter.Compression compression) throws IOException {
        try (OutputStream out = Files.newOutputStream(file);
             McapWriter w = new McapWriter(out, compression, 300)) {
            Map<String, Integer> channels = new HashMap<>();
            for (JsonNode e : expected) {
                String topic = e.get("topic").textValue();
                String type = e.get("type").textValue();
                if (!channels.containsKey(topic)) {
                    channels.put(topic, w.channel(topic, type, definition(type)));
                }
                w.write(channels.get(topic), e.get("log_time").longValue(),
                        (Map<String, Object>) JsonValues.plain(e.get("fields")));
            }
        }
    }

    @SuppressWarnings("unchecked")
    static void writeDb3(Path file, boolean humble) throws IOException {
        try (Db3Writer w = new Db3Writer(file, humble)) {
            Map<String, Integer> topics = new HashMap<>();
            for (JsonNode e : expected) {
                String topic = e.get("topic").textValue();
                String type = e.get("type").textValue();
                if (!topics.containsKey(topic)) {
                    topics.put(topic, w.topic(topic, type, definition(type)));
                }
                w.write(topics.get(topic), e.get("log_time").longValue(),
                        (Map<String, Object>) JsonValues.plain(e.get("fields")));
            }
        }
    }

    private static void assertMessages(JsonNode actual, String what) {
        assertEquals(expected.size(), actual.size(), what + ": messages");
        for (int i = 0; i < expected.size(); i++) {
            assertEquals(expected.get(i).get("topic"), actual.get(i).get("topic"), what);
            assertEquals(expected.get(i).get("log_time").longValue(), actual.get(i).get("log_time").longValue(), what);
            JsonValues.assertValue(expected.get(i).get("fields"), JsonValues.plain(actual.get(i).get("fields")),
                    what + " message " + (i + 1));
        }
    }

    @Test
    void pythonsMcapReaderDecodesPredmonsMcapInEveryCompression() throws Exception {
        for (McapWriter.Compression c : McapWriter.Compression.values()) {
            Path file = dir.resolve("predmon-" + c + ".mcap");
            writeMcap(file, c);
            assertMessages(JsonValues.parse(PythonBags.run("read_bag.py", file.toString())), file.toString());
        }
    }

    @Test
    void rosbagsReadsPredmonsSqlite3File() throws Exception {
        Path folder = dir.resolve("predmon-sqlite3");
        Files.createDirectories(folder);
        writeDb3(folder.resolve("predmon-sqlite3_0.db3"), false);
        Metadata.write(folder, List.of("predmon-sqlite3_0.db3"));
        assertMessages(JsonValues.parse(PythonBags.run("read_bag.py", folder.toString())), folder.toString());
    }

    @Test
    void predmonReadsWhatItWrote() throws IOException {
        for (McapWriter.Compression c : McapWriter.Compression.values()) {
            Path file = dir.resolve("own-" + c + ".mcap");
            writeMcap(file, c);
            assertDecoded(file);
        }
        Path db3 = dir.resolve("own.db3");
        writeDb3(db3, false);
        assertDecoded(db3);
    }

    private static void assertDecoded(Path file) throws IOException {
        Collected c = Collected.read(file);
        assertEquals(List.of(), c.problems, file.toString());
        assertEquals(expected.size(), c.messages.size(), file.toString());
        for (int i = 0; i < expected.size(); i++) {
            JsonValues.assertValue(expected.get(i).get("fields"), c.messages.get(i).fields(), file + " " + (i + 1));
        }
    }
}
