package dev.predmon.rosbag;

/** Where a reader of a ROS 2 recording delivers what it reads, in reading order. */
public interface BagSink {

    /** The next decoded message. */
    void message(BagMessage message);

    /**
     * Something that could not be read: one line naming the file, the record (its offset or its row) and what was
     * expected. Every message before it has been delivered.
     */
    void problem(String line);

    /**
     * Whether the messages of {@code topic} (of {@code type}, {@code pkg/msg/Type}) are wanted; asked once per topic
     * of each data file, before its first message. A topic not wanted is neither decoded nor delivered, and a topic
     * that could not be decoded is reported only if it is wanted. All topics by default.
     */
    default boolean wants(String topic, String type) {
        return true;
    }
}
