package dev.predmon.rosbag;

import java.nio.file.Path;
import java.util.Map;

/**
 * One message of a ROS 2 recording (a rosbag2 folder, an MCAP file or a sqlite3 {@code .db3} file), decoded from CDR
 * with the message definitions the recording carries.
 *
 * <p>Decoded values: a nested message is a {@code Map<String, Object>} in field order, an array or sequence a
 * {@code List<Object>}, every integer type a {@code Long} (a {@code uint64} above {@code Long.MAX_VALUE} keeps its
 * bits), {@code float32}/{@code float64} a {@code Double} (NaN stays NaN), {@code bool} a {@code Boolean}, {@code
 * string}/{@code wstring} a {@code String}.
 *
 * @param file         the data file the message was read from
 * @param index        1-based position of the message among the messages read from {@code file}, in reading order:
 *                     what a line number is to a text log
 * @param topic        its topic, e.g. {@code /battery_state}
 * @param type         its type as the recording names it, e.g. {@code sensor_msgs/msg/BatteryState}
 * @param logTimeNanos when the recorder received it, in nanoseconds since the epoch
 * @param fields       its decoded fields, by name
 */
public record BagMessage(Path file, long index, String topic, String type, long logTimeNanos,
                         Map<String, Object> fields) {
}
