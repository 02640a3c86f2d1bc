package dev.predmon.cli;

import dev.predmon.monitor.TickSeconds;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * {@code --timestamps}, {@code --heartbeat} and {@code --tick-seconds}: how watch's output reads while it follows logs
 * for hours.
 */
final class FollowOptions {

    private static final Pattern DURATION = Pattern.compile("(\\d+(?:\\.\\d+)?)(ms|s|m|h)?");

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    @Option(names = "--timestamps", description = "Start every text line of events with the wall-clock time (UTC, "
            + "ISO 8601, as 2026-11-25T17:40:01.123Z). JSON events always carry it as \"wallTime\".")
    boolean timestamps;

    private long heartbeatNanos;

    @Option(names = "--heartbeat", paramLabel = "DURATION", description = "Every DURATION (30s, 5m, 1h, 500ms; "
            + "seconds without a unit) print each log's line, run and latest forecast, so that a quiet watch is seen "
            + "to be alive. Off by default.")
    void heartbeat(String text) {
        Matcher m = DURATION.matcher(text.strip().toLowerCase(Locale.ROOT));
        double nanos = m.matches() ? Double.parseDouble(m.group(1)) * switch (m.group(2) == null ? "s" : m.group(2)) {
            case "ms" -> 1e6;
            case "m" -> 60e9;
            case "h" -> 3600e9;
            default -> 1e9;
        } : Double.NaN;
        if (!(nanos >= 1e6) || nanos > 1e18) {
            throw new ParameterException(mixee.commandLine(), "--heartbeat must be a duration of at least 1 ms, as "
                    + "30s, 5m or 1h, got '" + text + "'");
        }
        heartbeatNanos = (long) nanos;
    }

    private TickSeconds ticks = TickSeconds.NONE;

    @Option(names = "--tick-seconds", paramLabel = "S", description = "How many seconds a tick of the tree lasts, for "
            + "logs without time stamps (a console capture), which are counted in ticks: every time shown (events, "
            + "forecasts, leads, the page, hooks) is then in seconds, and a deadline of T seconds is T seconds of "
            + "ticks. Logs with time stamps are not affected.")
    void tickSeconds(double seconds) {
        if (!(seconds > 0) || seconds > 3600) {
            // a tick of an hour is already no behaviour tree's; beyond, times overflow to Infinity
            throw new ParameterException(mixee.commandLine(), "--tick-seconds must be a number of seconds above 0 "
                    + "and at most 3600, got " + seconds);
        }
        ticks = new TickSeconds(seconds);
    }

    /** How long a tick lasts, or {@link TickSeconds#NONE}. */
    TickSeconds ticks() {
        return ticks;
    }

    /** The pause between two heartbeats, in nanoseconds; 0 without {@code --heartbeat}. */
    long heartbeatNanos() {
        return heartbeatNanos;
    }
}
