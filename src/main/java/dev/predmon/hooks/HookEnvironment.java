package dev.predmon.hooks;

import dev.predmon.monitor.MonitorEvent;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The environment variables a hook command gets: an event's main fields, so that a one-line shell command can use
 * them without parsing JSON ({@code echo "warning $PREDMON_SCENARIO $PREDMON_BATTERY" | yarp write ...}). Numbers
 * are written as in the JSON; a value the event does not have (no battery reading yet) is the empty string.
 */
public final class HookEnvironment {

    private HookEnvironment() {
    }

    /**
     * PREDMON_EVENT ({@code warning} or {@code violation}), PREDMON_LOG, PREDMON_RUN, PREDMON_TIME, PREDMON_UNIT
     * ({@code s} or {@code ticks}), PREDMON_LINE, PREDMON_BATTERY; for a warning PREDMON_SCENARIO (the first faulty
     * scenario still matching) and PREDMON_SCENARIOS (all, comma-separated); for a violation PREDMON_PROPERTY and
     * PREDMON_BEFORE (the reading before the violating one).
     *
     * @throws IllegalArgumentException for events that run no hook
     */
    public static Map<String, String> of(String log, MonitorEvent event) {
        Map<String, String> env = new LinkedHashMap<>();
        if (event instanceof MonitorEvent.Warning w) {
            put(env, "warning", log, w.run(), w.time(), w.clock().unit(), w.line(), w.battery());
            env.put("PREDMON_SCENARIO", w.scenarios().isEmpty() ? "" : w.scenarios().get(0));
            env.put("PREDMON_SCENARIOS", String.join(",", w.scenarios()));
        } else if (event instanceof MonitorEvent.Violation v) {
            put(env, "violation", log, v.run(), v.time(), v.clock().unit(), v.line(), v.value());
            env.put("PREDMON_PROPERTY", v.property());
            env.put("PREDMON_BEFORE", text(v.before()));
        } else {
            throw new IllegalArgumentException("no hook runs for " + event);
        }
        return env;
    }

    private static void put(Map<String, String> env, String kind, String log, int run, double time, String unit,
                            long line, Double battery) {
        env.put("PREDMON_EVENT", kind);
        env.put("PREDMON_LOG", log);
        env.put("PREDMON_RUN", Integer.toString(run));
        env.put("PREDMON_TIME", Double.toString(time));
        env.put("PREDMON_UNIT", unit);
        env.put("PREDMON_LINE", Long.toString(line));
        env.put("PREDMON_BATTERY", text(battery));
    }

    private static String text(Double d) {
        return d == null ? "" : Double.toString(d);
    }
}
