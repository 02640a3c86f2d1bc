package dev.predmon.event;

import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.monitor.MonitorEvent;

import java.time.Instant;

/**
 * A monitor event of one watched log as it is sent: the typed event and its JSON object ({@link EventJson}, naming
 * the log), made once. The live page takes both (the tile reads the typed event, the page's stream gets the
 * {@link #line}); a hook command gets the line on its standard input.
 *
 * @param log   the log's name
 * @param event the event
 * @param json  its JSON object; shared by every receiver, so none may change it
 */
public record LogEvent(String log, MonitorEvent event, ObjectNode json) {

    /** {@code e} of {@code log}, sent at wall-clock time {@code at}. */
    public static LogEvent of(String log, MonitorEvent e, Instant at) {
        return new LogEvent(log, e, EventJson.of(e, log, at));
    }

    /** {@code e} of {@code log}, sent now. */
    public static LogEvent of(String log, MonitorEvent e) {
        return of(log, e, Instant.now());
    }

    /** The JSON object as one line. */
    public String line() {
        return EventJson.line(json);
    }
}
