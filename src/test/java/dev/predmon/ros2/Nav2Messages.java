package dev.predmon.ros2;

import dev.predmon.rosbag.BagMessage;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** Decoded nav2 messages as a reader delivers them ({@link BagMessage}'s value types), for tests. */
final class Nav2Messages {

    static final String BATTERY = "sensor_msgs/msg/BatteryState";
    static final String STATUS = "action_msgs/msg/GoalStatusArray";

    private long index;

    private BagMessage next(String topic, String type, double seconds, Map<String, Object> fields) {
        return new BagMessage(null, ++index, topic, type, Math.round(seconds * 1e9), fields);
    }

    BagMessage battery(double seconds, double percentage) {
        Map<String, Object> f = new LinkedHashMap<>();
        f.put("header", Map.of("stamp", Map.of("sec", (long) seconds, "nanosec", 0L), "frame_id", "base_link"));
        f.put("voltage", 24.1);
        f.put("percentage", percentage);
        f.put("present", true);
        f.put("cell_voltage", List.of());
        return next("/battery_state", BATTERY, seconds, f);
    }

    /** A status array of goals: each {@code {uuidByte, status}}. */
    BagMessage goals(String topic, double seconds, int[]... goals) {
        List<Object> list = new ArrayList<>();
        for (int[] g : goals) {
            List<Object> uuid = new ArrayList<>();
            for (int i = 0; i < 16; i++) {
                uuid.add(i == 15 ? (long) g[0] : 0L);
            }
            list.add(Map.of("goal_info", Map.of("goal_id", Map.of("uuid", uuid),
                    "stamp", Map.of("sec", 1L, "nanosec", 0L)), "status", (long) g[1]));
        }
        return next(topic, STATUS, seconds, Map.of("status_list", list));
    }

    BagMessage navigation(double seconds, int[]... goals) {
        return goals("/navigate_to_pose/_action/status", seconds, goals);
    }

    BagMessage treeLog(double seconds, String node, String previous, String current) {
        return next("/behavior_tree_log", "nav2_msgs/msg/BehaviorTreeLog", seconds, Map.of("timestamp",
                Map.of("sec", 1L, "nanosec", 0L), "event_log", List.of(Map.of("node_name", node, "uid", 3L,
                        "previous_status", previous, "current_status", current))));
    }

    BagMessage log(double seconds, long level, String name, String text) {
        return next("/rosout", "rcl_interfaces/msg/Log", seconds, Map.of("level", level, "name", name, "msg", text));
    }

    BagMessage diagnostics(double seconds, String name, long level) {
        return next("/diagnostics", "diagnostic_msgs/msg/DiagnosticArray", seconds, Map.of("status",
                List.of(Map.of("level", level, "name", name, "message", "", "hardware_id", "", "values", List.of()))));
    }
}
