package dev.predmon.hooks;

import dev.predmon.Terminal;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.property.Property;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The environment variables a hook command gets: an event's main fields, so that a one-line shell command can use
 * them without parsing JSON ({@code echo "warning $PREDMON_SCENARIO $PREDMON_VALUE" | yarp write ...}). Numbers are
 * rounded as the live page shows them (the JSON on standard input keeps every digit); a value the event does not
 * have (no reading yet, no forecast) is the empty string.
 */
public final class HookEnvironment {

    private HookEnvironment() {
    }

    /**
     * PREDMON_EVENT ({@code warning}, {@code violation} or {@code recovered}), PREDMON_LOG (control characters and
     * bidirectional overrides escaped as on the terminal), PREDMON_RUN, PREDMON_TIME, PREDMON_UNIT
     * ({@code s} or {@code ticks}), PREDMON_LINE, PREDMON_PROPERTY (the property's id), PREDMON_VALUE (its last
     * value, two decimals; empty for a property without one, such as a bounded response) and PREDMON_BATTERY (the
     * same, the older name); for a warning PREDMON_SCENARIO (the faulty
     * scenario the run is most like), PREDMON_SCENARIOS (the faulty scenarios still matching, comma-separated),
     * PREDMON_PROBABILITY (two decimals; for a deadline's warning its probability of a miss, empty past every training
 * obligation) and PREDMON_TIME_TO_VIOLATION (in PREDMON_UNIT, as the page rounds it; empty for a deadline); for
     * a violation PREDMON_BEFORE (the value before the violating one); for a recovery ({@code recovered}) PREDMON_CAUSE
     * ({@code forecast}, {@code action}, {@code property}, or {@code discharged} for a deadline) and PREDMON_PROPERTY
     * the property whose alarm ended.
     *
     * @param bound the property's bound, below which it is violated (NaN when not known): a value below it is rounded
     *              down, as on the page, so that a violating 19.995 never reads as the bound itself
     * @throws IllegalArgumentException for events that run no hook
     */
    public static Map<String, String> of(String log, MonitorEvent event, double bound) {
        return of(log, event, bound, Map.of());
    }

    /**
     * As above, with the property's words from {@code properties} (by id): PREDMON_PROPERTY_NAME (the property in
     * words: {@code a grasp succeeds within 8 attempts}), PREDMON_ACTION (what an operator should do, or empty) and
     * PREDMON_WHAT (the event in an operator's words: what violated the property, why it was warned of, why its alarm
     * ended).
     */
    public static Map<String, String> of(String log, MonitorEvent event, double bound,
                                         Map<String, Property> properties) {
        Map<String, String> env = base(log, event, bound);
        Property p = properties.get(env.get("PREDMON_PROPERTY"));
        String name = event instanceof MonitorEvent.Violation v && v.name() != null ? v.name()
                : p == null ? "" : p.name();
        env.put("PREDMON_PROPERTY_NAME", name);
        env.put("PREDMON_ACTION", p == null || p.action() == null ? "" : p.action());
        env.put("PREDMON_WHAT", event instanceof MonitorEvent.Violation v ? v.what() == null ? "" : v.what()
                : event instanceof MonitorEvent.Warning w ? w.reason() : ((MonitorEvent.Recovered) event).reason());
        return env;
    }

    private static Map<String, String> base(String log, MonitorEvent event, double bound) {
        Map<String, String> env = new LinkedHashMap<>();
        if (event instanceof MonitorEvent.Warning w) {
            put(env, "warning", log, w.run(), w.time(), w.clock().unit(), w.line(), w.property(), value(w.value(), bound));
            env.put("PREDMON_SCENARIO", w.scenario() == null ? "" : w.scenario());
            env.put("PREDMON_SCENARIOS", String.join(",", w.scenarios()));
            Forecast f = w.forecast();
            env.put("PREDMON_PROBABILITY", f != null ? fixed(f.probability(), 2, RoundingMode.HALF_UP)
                    : w.deadline() != null && !w.deadline().novel()
                    ? fixed(w.deadline().probability(), 2, RoundingMode.HALF_UP) : "");
            env.put("PREDMON_TIME_TO_VIOLATION", f == null || !ForecastWords.inSight(f) ? ""
                    : span(f.timeToViolation(), w.clock().unit()));
        } else if (event instanceof MonitorEvent.Recovered r) {
            put(env, "recovered", log, r.run(), r.time(), r.clock().unit(), r.line(), r.property(),
                    value(Double.isNaN(r.value()) ? null : r.value(), bound));
            env.put("PREDMON_CAUSE", r.cause());
        } else if (event instanceof MonitorEvent.Violation v) {
            put(env, "violation", log, v.run(), v.time(), v.clock().unit(), v.line(), v.property(),
                    value(v.value(), bound));
            env.put("PREDMON_BEFORE", value(v.before(), bound));
        } else {
            throw new IllegalArgumentException("no hook runs for " + event);
        }
        return env;
    }

    /** As above, for a property whose bound is not known. */
    public static Map<String, String> of(String log, MonitorEvent event) {
        return of(log, event, Double.NaN);
    }

    private static void put(Map<String, String> env, String kind, String log, int run, double time, String unit,
                            long line, String property, String value) {
        env.put("PREDMON_EVENT", kind);
        // a file name's newline or ESC would make a one-line recipe (echo ... | yarp write) send two lines
        env.put("PREDMON_LOG", Terminal.line(log));
        env.put("PREDMON_RUN", Integer.toString(run));
        env.put("PREDMON_TIME", Double.toString(time));
        env.put("PREDMON_UNIT", unit);
        env.put("PREDMON_LINE", Long.toString(line));
        env.put("PREDMON_PROPERTY", property == null ? "" : property);
        env.put("PREDMON_VALUE", value);
        env.put("PREDMON_BATTERY", value); // the older name of PREDMON_VALUE, kept for existing hook commands
    }

    /** A value of the property with two decimals; below the bound rounded down, as the page shows it. */
    static String value(Double v, double bound) {
        if (v == null || !Double.isFinite(v)) {
            return "";
        }
        return fixed(v, 2, v < bound ? RoundingMode.FLOOR : RoundingMode.HALF_UP);
    }

    /** A duration as the page shows it: whole ticks; seconds with 0, 1 or 2 decimals as it is long or short. */
    static String span(double d, String unit) {
        if (!Double.isFinite(d)) {
            return "";
        }
        int digits = unit.equals("ticks") || Math.abs(d) >= 100 ? 0 : Math.abs(d) >= 10 ? 1 : 2;
        return fixed(d, digits, RoundingMode.HALF_UP);
    }

    private static String fixed(double x, int digits, RoundingMode mode) {
        if (Math.abs(x) >= 1e15) {
            // past the digits a double holds: six significant ones in scientific notation, not hundreds of digits
            return new BigDecimal(x).round(new MathContext(6)).stripTrailingZeros().toString().replace("E+", "e");
        }
        return BigDecimal.valueOf(x).setScale(digits, mode).toPlainString();
    }
}
