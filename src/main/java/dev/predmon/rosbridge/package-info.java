/**
 * A live robot through rosbridge (the rosbridge v2 protocol over a WebSocket): subscribes to an abstraction's topics,
 * turns each {@code publish} into a {@link dev.predmon.rosbag.BagMessage} for the same mapping as a recording's, and
 * publishes each property's verdict back as {@code diagnostic_msgs/DiagnosticArray}. Used by {@code watch}; the
 * mapping knows nothing of it.
 */
package dev.predmon.rosbridge;
