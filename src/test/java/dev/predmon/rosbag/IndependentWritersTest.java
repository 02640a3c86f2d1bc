package dev.predmon.rosbag;

import com.fasterxml.jackson.databind.JsonNode;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Bags written by writers that are not predmon's ({@code rosbags}: sqlite3 and uncompressed MCAP; {@code
 * mcap-ros2-support}: zstd and lz4 MCAP) decode to the values the writer was given, field by field, and every form
 * to the same messages.
 */
class IndependentWritersTest {

    @TempDir
    static Path dir;
    static JsonNode expected;

    @BeforeAll
    static void write() throws Exception {
        PythonBags.run("write_bags.py", dir.toString());
        expected = JsonValues.parse(Files.readString(dir.resolve("expected.json")));
    }

    static List<Path> forms() {
        return List.of(dir.resolve("rosbags_sqlite3"), dir.resolve("rosbags_mcap"), dir.resolve("zstd.mcap"),
                dir.resolve("lz4.mcap"), dir.resolve("rosbags_sqlite3").resolve("rosbags_sqlite3.db3"),
                dir.resolve("rosbags_mcap").resolve("rosbags_mcap.mcap"));
    }

    @Test
    void everyFormDecodesToTheValuesWritten() throws IOException {
        for (Path form : forms()) {
            Collected c = Collected.read(form);
            assertEquals(List.of(), c.problems, form + ": problems");
            assertEquals(expected.size(), c.messages.size(), form + ": messages");
            for (int i = 0; i < expected.size(); i++) {
                JsonNode e = expected.get(i);
                BagMessage m = c.messages.get(i);
                String at = dir.relativize(form) + " message " + (i + 1);
                assertEquals(e.get("topic").textValue(), m.topic(), at);
                assertEquals(e.get("type").textValue(), m.type(), at);
                assertEquals(e.get("log_time").longValue(), m.logTimeNanos(), at);
                assertEquals(i + 1, m.index(), at);
                JsonValues.assertValue(e.get("fields"), m.fields(), at + " " + m.topic());
            }
        }
    }

    @Test
    void everyFormGivesTheSameMessages() throws IOException {
        List<List<Object>> first = null;
        for (Path form : forms()) {
            List<List<Object>> these = new ArrayList<>();
            for (BagMessage m : Collected.read(form).messages) {
                these.add(List.of(m.topic(), m.type(), m.logTimeNanos(), m.fields()));
            }
            if (first == null) {
                first = these;
            }
            assertEquals(first, these, form.toString());
        }
    }

    @Test
    void theFormsAreRecognisedByContentWhateverTheirNames() throws IOException {
        for (Path form : forms()) {
            if (Files.isRegularFile(form)) {
                Path renamed = dir.resolve("renamed-" + form.getFileName() + ".bin");
                Files.copy(form, renamed);
                assertTrue(Bags.looksLikeBag(renamed), renamed.toString());
                assertEquals(expected.size(), Collected.read(renamed).messages.size(), renamed.toString());
            } else {
                assertTrue(Bags.looksLikeBag(form), form.toString());
            }
        }
    }
}
