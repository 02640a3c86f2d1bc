package dev.predmon.watch;

import dev.predmon.monitor.TickSeconds;

/**
 * How a watch session reports.
 *
 * @param json           events as JSON lines on stdout, rather than text
 * @param eliminations   also print each model's elimination (JSON always does)
 * @param several        whether events must name their log (several logs, or a directory or glob)
 * @param noFollow       each log is read to its end and judged as a whole, rather than followed
 * @param stamp          what begins each text line ({@link Stamp#WALL_CLOCK} with {@code --timestamps})
 * @param heartbeatNanos the pause between two heartbeat lines while following; 0 for none
 * @param ticks          how long a tick lasts, so that logs counted in ticks report seconds
 */
public record WatchSettings(boolean json, boolean eliminations, boolean several, boolean noFollow, Stamp stamp,
                            long heartbeatNanos, TickSeconds ticks) {

    /** Text or JSON events of logs followed, eliminations as asked, no stamp, no heartbeat, ticks as ticks. */
    public static WatchSettings of(boolean json, boolean eliminations, boolean several, boolean noFollow) {
        return new WatchSettings(json, eliminations, several, noFollow, Stamp.NONE, 0, TickSeconds.NONE);
    }
}
