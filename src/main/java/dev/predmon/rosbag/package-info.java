/**
 * Reads ROS 2 recordings (rosbag2 folders, MCAP and sqlite3 files) into decoded {@link dev.predmon.rosbag.BagMessage}s,
 * and writes them. It knows nothing of the monitor: mapping messages to records is another package's job.
 */
package dev.predmon.rosbag;
