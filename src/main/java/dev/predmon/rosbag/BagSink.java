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
}
