package dev.predmon.ros2;

import dev.predmon.rosbag.BagSink;

import java.io.IOException;
import java.nio.file.Path;

/** How recordings are read: {@code dev.predmon.rosbag}'s readers, or the messages a test makes. */
public interface BagInput {

    /** Whether {@code path} is a ROS 2 recording (a rosbag2 folder, an MCAP or sqlite3 file), by its content. */
    boolean looksLikeBag(Path path);

    /** Reads the recording at {@code path} whole, delivering every message and problem to {@code sink}. */
    void read(Path path, BagSink sink) throws IOException;

    /**
     * Follows the recording at {@code path} while it is written (it need not exist yet): each {@link Follow#poll()}
     * delivers the messages written since the last.
     */
    Follow follow(Path path, BagSink sink);

    /** A recording being followed. */
    interface Follow extends AutoCloseable {

        /** Delivers what was written since the last call, without blocking; whether anything was. */
        boolean poll() throws IOException;

        @Override
        void close() throws IOException;
    }
}
