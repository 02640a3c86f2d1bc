package dev.predmon.ros2;

import dev.predmon.parse.LogFormat;
import dev.predmon.rosbag.BagSink;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** The input format with the recordings read by {@code dev.predmon.rosbag}'s readers. */
public final class Recordings {

    private Recordings() {
    }

    /**
     * Whether {@code path} is a ROS 2 recording: a rosbag2 folder, an MCAP or sqlite3 file (by content; a file named
     * {@code .mcap} or {@code .db3} too, which a recorder may not have written its first bytes to yet).
     */
    public static boolean isRecording(Path path) {
        if (Files.isRegularFile(path)) {
            String name = path.getFileName().toString();
            if (name.endsWith(".mcap") || name.endsWith(".db3")) {
                return true;
            }
        }
        return READERS.looksLikeBag(path);
    }

    /** YARP logs, and ROS 2 recordings mapped by {@code rules}. */
    public static LogFormat format(List<TopicRule> rules) {
        return new Ros2Format(rules, READERS);
    }

    // MERGE-PENDING: replaced by dev.predmon.rosbag.Bags once the readers land.
    static final BagInput READERS = new BagInput() {
        @Override
        public boolean looksLikeBag(Path path) {
            return false;
        }

        @Override
        public void read(Path path, BagSink sink) throws IOException {
            throw new IOException(path + ": cannot read ROS 2 recordings yet");
        }

        @Override
        public Follow follow(Path path, BagSink sink) {
            throw new UnsupportedOperationException();
        }
    };
}
