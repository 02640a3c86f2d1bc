package dev.predmon.simulate;

import dev.predmon.parse.Decimals;
import dev.predmon.parse.RecordKind;
import dev.predmon.rosbag.BagMessage;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A simulated run as a robot on ROS 2 navigation (nav2) would record it with {@code ros2 bag record}: the battery
 * driver's {@code /battery_state}, and the status arrays of the {@code navigate_to_pose} and {@code dock_robot}
 * actions. The YARP monitor's messages become what nav2 publishes for the same happenings, at the same times:
 * <ul>
 *   <li>a {@code level} reply of the battery component: a {@code sensor_msgs/msg/BatteryState} whose
 *       {@code percentage} is the level as a fraction (0..1, as the message's specification says, in float32), its
 *       {@code power_supply_status} charging or discharging as the last {@code charging_status} reply said;</li>
 *   <li>a {@code goTo}: a new goal of {@code dock_robot} (to the charging station) or {@code navigate_to_pose}
 *       (anywhere else), executing; a {@code getStatus} reply SUCCESS or ABORT: that goal succeeded or aborted; a
 *       {@code halt}: succeeded when {@code isAtLocation} last said the robot is there (the R1 tree ends a navigation
 *       so), else canceled. Each {@code getStatus} reply publishes the action's status array again, every goal of
 *       the run in it, as an action server's array repeats its live and recently finished goals.</li>
 * </ul>
 * Ticks, the tree's calls to its skills, {@code isAtLocation} and the arm have no nav2 topic and are left out.
 */
public final class Nav2Recording {

    /** The topic of the battery driver. */
    public static final String BATTERY = "/battery_state";
    public static final String BATTERY_TYPE = "sensor_msgs/msg/BatteryState";
    public static final String NAVIGATE = "/navigate_to_pose/_action/status";
    public static final String DOCK = "/dock_robot/_action/status";
    public static final String STATUS_TYPE = "action_msgs/msg/GoalStatusArray";

    private static final long EXECUTING = 2;
    private static final long SUCCEEDED = 4;
    private static final long CANCELED = 5;
    private static final long ABORTED = 6;
    /** sensor_msgs/BatteryState's POWER_SUPPLY_STATUS_CHARGING and _DISCHARGING. */
    private static final long CHARGING = 1;
    private static final long DISCHARGING = 2;

    /** A goal of one of the two actions. */
    private static final class Goal {
        final List<Object> uuid;
        final long sec;
        final long nanosec;
        long status = EXECUTING;

        Goal(List<Object> uuid, long timeMicros) {
            this.uuid = uuid;
            this.sec = timeMicros / 1_000_000;
            this.nanosec = timeMicros % 1_000_000 * 1000;
        }
    }

    private final List<BagMessage> out = new ArrayList<>();
    private final Map<String, List<Goal>> goals = new LinkedHashMap<>();
    private final Map<String, Goal> current = new LinkedHashMap<>();
    /** Per action, whether the last {@code isAtLocation} of its destination said the robot is there. */
    private final Map<String, Boolean> arrived = new LinkedHashMap<>();
    private final long seed;
    private long charging = DISCHARGING;
    private long goalsMade;

    private Nav2Recording(long seed) {
        this.seed = seed;
        goals.put(NAVIGATE, new ArrayList<>());
        goals.put(DOCK, new ArrayList<>());
    }

    /** The messages of {@code runs}, one after another, in time order, indexed from 1. */
    public static List<BagMessage> of(List<SimRun> runs) {
        Nav2Recording r = new Nav2Recording(runs.isEmpty() ? 0 : runs.get(0).seed());
        for (SimRun run : runs) {
            for (SimEvent e : run.events()) {
                r.take(e);
            }
        }
        return List.copyOf(r.out);
    }

    /** The messages of one run. */
    public static List<BagMessage> of(SimRun run) {
        return of(List.of(run));
    }

    private void take(SimEvent e) {
        String p = e.protocol();
        String c = e.command();
        if (p.equals("BatteryReader") && e.kind() == RecordKind.REPLY) {
            if (c.equals("charging_status")) {
                charging = e.reply().equals("1") ? CHARGING : DISCHARGING;
            } else if (c.equals("level")) {
                double level = Decimals.parse(e.reply());
                if (!Double.isNaN(level)) {
                    battery(e.timeMicros(), level);
                }
            }
        } else if (p.equals("GoTo")) {
            String topic = e.argument().equals("charging_station") ? DOCK : NAVIGATE;
            if (c.equals("goTo") && e.kind() == RecordKind.COMMAND) {
                arrived.remove(topic);
                Goal g = new Goal(uuid(++goalsMade), e.timeMicros());
                goals.get(topic).add(g);
                current.put(topic, g);
                status(topic, e.timeMicros());
            } else if (c.equals("getStatus") && e.kind() == RecordKind.REPLY) {
                end(topic, e.reply().equals("2") ? SUCCEEDED : e.reply().equals("3") ? ABORTED : -1);
                status(topic, e.timeMicros());
            } else if (c.equals("isAtLocation") && e.kind() == RecordKind.REPLY) {
                arrived.put(topic, e.reply().equals("1") || e.reply().equals("27503"));
            } else if (c.equals("halt") && e.kind() == RecordKind.COMMAND) {
                // The R1 tree halts a navigation once its IsAt condition sees the robot there: nav2 would have
                // succeeded the goal. A halt anywhere else cancels it.
                end(topic, Boolean.TRUE.equals(arrived.get(topic)) ? SUCCEEDED : CANCELED);
                status(topic, e.timeMicros());
            }
        }
    }

    private void end(String topic, long status) {
        Goal g = current.get(topic);
        if (g != null && status > 0) {
            g.status = status;
            current.remove(topic);
        }
    }

    private void battery(long micros, double level) {
        Map<String, Object> f = new LinkedHashMap<>();
        f.put("header", header(micros));
        f.put("voltage", (double) (float) (22.0 + 3.0 * level / 100));
        f.put("percentage", (double) (float) (level / 100));
        f.put("power_supply_status", charging);
        f.put("present", true);
        f.put("location", "slot0");
        add(BATTERY, BATTERY_TYPE, micros, f);
    }

    private void status(String topic, long micros) {
        List<Object> list = new ArrayList<>();
        for (Goal g : goals.get(topic)) {
            list.add(Map.of("goal_info", Map.of("goal_id", Map.of("uuid", g.uuid),
                    "stamp", Map.of("sec", g.sec, "nanosec", g.nanosec)), "status", g.status));
        }
        add(topic, STATUS_TYPE, micros, Map.of("status_list", list));
    }

    private void add(String topic, String type, long micros, Map<String, Object> fields) {
        out.add(new BagMessage(null, out.size() + 1, topic, type, micros * 1000, fields));
    }

    private static Map<String, Object> header(long micros) {
        return Map.of("stamp", Map.of("sec", micros / 1_000_000, "nanosec", micros % 1_000_000 * 1000),
                "frame_id", "base_link");
    }

    /** A goal's 16-byte id: the run's seed and the goal's number, as a client library draws a random one. */
    private List<Object> uuid(long n) {
        long bits = seed * 0x9E3779B97F4A7C15L + n;
        List<Object> bytes = new ArrayList<>(16);
        for (int i = 0; i < 16; i++) {
            bytes.add((bits >>> (8 * (i % 8)) ^ (i < 8 ? 0 : n * 31)) & 0xff);
        }
        return List.copyOf(bytes);
    }
}
