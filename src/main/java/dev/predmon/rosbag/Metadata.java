package dev.predmon.rosbag;

import dev.predmon.files.AtomicFiles;
import org.snakeyaml.engine.v2.api.Dump;
import org.snakeyaml.engine.v2.api.DumpSettings;
import org.snakeyaml.engine.v2.common.FlowStyle;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Writes the {@code metadata.yaml} of a rosbag2 folder (version 9, as Jazzy's recorder and {@code rosbags} write
 * it) from what its data files hold, so that {@code ros2 bag info}, {@code ros2 bag play} and other readers take a
 * folder predmon wrote.
 */
public final class Metadata {

    private Metadata() {
    }

    /**
     * Reads the data files of {@code folder}, in the order given, and writes its {@code metadata.yaml} (completely
     * or not at all).
     *
     * @param files the data files' names, in order, each in {@code folder}
     * @throws IOException if a file cannot be read or holds something that cannot be read
     */
    public static void write(Path folder, List<String> files) throws IOException {
        AtomicFiles.replace(folder.resolve(BagFolder.METADATA), describe(folder, files));
    }

    /** The text of {@link #write}. */
    static String describe(Path folder, List<String> files) throws IOException {
        Map<String, Object[]> topics = new LinkedHashMap<>(); // topic -> {type, count}
        List<Object> described = new ArrayList<>();
        long first = Long.MAX_VALUE;
        long last = Long.MIN_VALUE;
        long total = 0;
        String storage = "mcap";
        for (String name : files) {
            Path file = folder.resolve(name);
            long[] span = {Long.MAX_VALUE, Long.MIN_VALUE, 0};
            List<String> problems = new ArrayList<>();
            Bags.read(file, new BagSink() {
                @Override
                public void message(BagMessage m) {
                    topics.computeIfAbsent(m.topic(), t -> new Object[] {m.type(), 0L})[1] =
                            (Long) topics.get(m.topic())[1] + 1;
                    span[0] = Math.min(span[0], m.logTimeNanos());
                    span[1] = Math.max(span[1], m.logTimeNanos());
                    span[2]++;
                }

                @Override
                public void problem(String line) {
                    problems.add(line);
                }
            });
            if (!problems.isEmpty()) {
                throw new IOException(problems.get(0));
            }
            storage = BagFolder.storage(file) == BagFolder.Storage.SQLITE3 ? "sqlite3" : "mcap";
            described.add(map("duration", nanos("nanoseconds", span[2] == 0 ? 0 : span[1] - span[0]),
                    "message_count", span[2], "path", name,
                    "starting_time", nanos("nanoseconds_since_epoch", span[2] == 0 ? 0 : span[0])));
            first = Math.min(first, span[0]);
            last = Math.max(last, span[1]);
            total += span[2];
        }
        List<Object> counts = new ArrayList<>();
        topics.forEach((name, v) -> counts.add(map("message_count", v[1], "topic_metadata", map("name", name,
                "offered_qos_profiles", "", "serialization_format", "cdr", "type", v[0],
                "type_description_hash", ""))));
        Map<String, Object> info = map("compression_format", "", "compression_mode", "", "custom_data", map(),
                "duration", nanos("nanoseconds", total == 0 ? 0 : last - first), "files", described,
                "message_count", total, "relative_file_paths", List.copyOf(files), "ros_distro", "predmon",
                "starting_time", nanos("nanoseconds_since_epoch", total == 0 ? 0 : first),
                "storage_identifier", storage, "topics_with_message_count", counts, "version", 9);
        return new Dump(DumpSettings.builder().setDefaultFlowStyle(FlowStyle.BLOCK).build())
                .dumpToString(map("rosbag2_bagfile_information", info));
    }

    private static Map<String, Object> nanos(String key, long value) {
        return map(key, value);
    }

    private static Map<String, Object> map(Object... keysAndValues) {
        Map<String, Object> m = new LinkedHashMap<>();
        for (int i = 0; i < keysAndValues.length; i += 2) {
            m.put((String) keysAndValues[i], keysAndValues[i + 1]);
        }
        return m;
    }
}
