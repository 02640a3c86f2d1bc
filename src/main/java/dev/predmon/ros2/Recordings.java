package dev.predmon.ros2;

import dev.predmon.parse.LogFormat;
import dev.predmon.rosbag.BagFollower;
import dev.predmon.rosbag.BagSink;
import dev.predmon.rosbag.Bags;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/** The input format with the recordings read by {@code dev.predmon.rosbag}'s readers, and what a recording is. */
public final class Recordings {

    private static final Pattern DATA_FILE = Pattern.compile(".*\\.(mcap|db3)");

    private Recordings() {
    }

    /**
     * Whether {@code path} is one ROS 2 recording: an MCAP or sqlite3 file (by content, or by a name ending in
     * {@code .mcap} or {@code .db3}, which a recorder may not have written its first bytes to yet), or a rosbag2
     * folder: one with a {@code metadata.yaml}, or whose data files are all named as the recorder names its split
     * files, {@code <folder>_<n>.mcap}. A folder of other data files is a folder of recordings (a fleet's), not one.
     */
    public static boolean isRecording(Path path) {
        if (Files.isDirectory(path)) {
            if (Files.isRegularFile(path.resolve("metadata.yaml"))) {
                return true;
            }
            String folder = path.getFileName() == null ? "" : path.getFileName().toString();
            Pattern split = Pattern.compile(Pattern.quote(folder) + "_[0-9]+\\.(mcap|db3)");
            try (Stream<Path> files = Files.list(path)) {
                List<String> data = files.map(f -> f.getFileName().toString())
                        .filter(n -> DATA_FILE.matcher(n).matches()).toList();
                return !data.isEmpty() && data.stream().allMatch(n -> split.matcher(n).matches());
            } catch (IOException e) {
                return false;
            }
        }
        if (Files.isRegularFile(path)) {
            String name = path.getFileName().toString();
            return name.endsWith(".mcap") || name.endsWith(".db3") || Bags.looksLikeBag(path);
        }
        return false;
    }

    /** YARP logs, and ROS 2 recordings mapped by {@code rules}. */
    public static LogFormat format(List<TopicRule> rules) {
        return new Ros2Format(rules, READERS);
    }

    /** {@code dev.predmon.rosbag}'s readers. */
    static final BagInput READERS = new BagInput() {
        @Override
        public boolean looksLikeBag(Path path) {
            return isRecording(path);
        }

        @Override
        public void read(Path path, BagSink sink) throws IOException {
            Bags.read(path, sink);
        }

        @Override
        public Follow follow(Path path, BagSink sink) {
            BagFollower follower = new BagFollower(path, sink);
            return new Follow() {
                @Override
                public boolean poll() throws IOException {
                    return follower.poll() > 0;
                }

                @Override
                public void close() throws IOException {
                    follower.close();
                }
            };
        }
    };
}
