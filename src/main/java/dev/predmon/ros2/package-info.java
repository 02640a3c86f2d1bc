/**
 * Maps the messages of ROS 2 recordings ({@link dev.predmon.rosbag.BagMessage}s, from a file or from any other stream)
 * to monitor records by the rules of an abstraction file's {@code ros2} section, and offers the recordings as a second
 * {@link dev.predmon.parse.LogFormat}: the stages above see records only, and never learn that ROS exists.
 */
package dev.predmon.ros2;
