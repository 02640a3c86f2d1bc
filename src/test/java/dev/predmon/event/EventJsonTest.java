package dev.predmon.event;

import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.Clock;
import org.junit.jupiter.api.Test;

import java.time.Instant;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

/**
 * The event JSON that scripts, the page and the hooks read: its fields, their order and their values, written out
 * in full, so that a change to any of them shows here first.
 */
class EventJsonTest {

    private static final Instant AT = Instant.parse("2026-11-25T17:40:01.123Z");

    @Test
    void aWarningNamesItsLogRightAfterTheEventAndItsWallTimeLast() {
        MonitorEvent.Warning w = new MonitorEvent.Warning(29.5, 7127, List.of("depleted"), 27.83, 14, Clock.SECONDS,
                1, WarningRule.MATCH, null, "the run can only be faulty scenario depleted");
        assertEquals("{\"event\":\"warning\",\"log\":\"robot-1.log\",\"time\":29.5,\"unit\":\"s\",\"line\":7127,"
                + "\"run\":1,\"property\":null,\"scenario\":\"depleted\",\"scenarios\":[\"depleted\"],"
                + "\"battery\":27.83,\"pairs\":14,\"rule\":\"match\",\"clause\":\"matching\","
                + "\"reason\":\"the run can only be faulty scenario depleted\",\"forecast\":null,\"deadline\":null,"
                + "\"wallTime\":\"2026-11-25T17:40:01.123Z\"}", EventJson.line(EventJson.of(w, "robot-1.log", AT)));
    }

    @Test
    void anotherPropertysViolationHasNoBatteryAndOneLogHasNoLogField() {
        MonitorEvent.Violation v = new MonitorEvent.Violation(88, 157, "no-abort", "navigation never aborts", null,
                null, "GoTo/getStatus reply 3", Clock.TICKS, 0, false);
        assertEquals("{\"event\":\"violation\",\"time\":88.0,\"unit\":\"ticks\",\"line\":157,\"run\":0,"
                + "\"property\":\"no-abort\",\"name\":\"navigation never aborts\",\"value\":null,\"battery\":null,"
                + "\"before\":null,\"what\":\"GoTo/getStatus reply 3\",\"wallTime\":\"2026-11-25T17:40:01.123Z\"}",
                EventJson.line(EventJson.of(v, null, AT)));
    }

    @Test
    void aLogEventsLineIsItsJsonNamingTheLog() {
        LogEvent sent = LogEvent.of("a.log", new MonitorEvent.NoMatch(5, 40, Clock.SECONDS, 0), AT);
        assertEquals("{\"event\":\"no-match\",\"log\":\"a.log\",\"time\":5.0,\"unit\":\"s\",\"line\":40,\"run\":0,"
                + "\"wallTime\":\"2026-11-25T17:40:01.123Z\"}", sent.line());
        assertThrows(IllegalArgumentException.class, () -> EventJson.of(new MonitorEvent.Unmapped(1, 2, "X/y"),
                null, AT), "an unmapped message goes to stderr, it is no JSON event");
    }
}
