package dev.predmon.event;

import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.forecast.Survival;
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
                + "\"value\":27.83,\"battery\":27.83,\"pairs\":14,\"rule\":\"match\",\"clause\":\"matching\","
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
    void theWatchedValueIsInValueAndUnderItsOlderNameBattery() {
        MonitorEvent.Violation v = new MonitorEvent.Violation(34.6, 8219, "battery", 15.86, 20.18, Clock.SECONDS, 0);
        assertEquals("{\"event\":\"violation\",\"time\":34.6,\"unit\":\"s\",\"line\":8219,\"run\":0,"
                + "\"property\":\"battery\",\"name\":\"battery\",\"value\":15.86,\"battery\":15.86,"
                + "\"before\":20.18,\"what\":null,\"wallTime\":\"2026-11-25T17:40:01.123Z\"}",
                EventJson.line(EventJson.of(v, null, AT)));
        MonitorEvent.Recovered r = new MonitorEvent.Recovered(41.2, 9950, "property", 21.5, "the property holds again",
                Clock.SECONDS, 0, "battery");
        assertEquals("{\"event\":\"recovered\",\"time\":41.2,\"unit\":\"s\",\"line\":9950,\"run\":0,"
                + "\"cause\":\"property\",\"value\":21.5,\"battery\":21.5,\"reason\":\"the property holds again\","
                + "\"property\":\"battery\",\"wallTime\":\"2026-11-25T17:40:01.123Z\"}",
                EventJson.line(EventJson.of(r, null, AT)));
    }

    @Test
    void aDeadlinesWarningAndRecoveryHaveNoValue() {
        MonitorEvent.Warning w = new MonitorEvent.Warning(345, 7240, List.of(), null, 2, Clock.TICKS, 0,
                WarningRule.FORECAST, null, "pending", MonitorEvent.Clause.DEADLINE, null, "navigation-in-time",
                new Survival.Estimate(Double.NaN, 57, 0, 0, true));
        assertEquals("{\"event\":\"warning\",\"time\":345.0,\"unit\":\"ticks\",\"line\":7240,\"run\":0,"
                + "\"property\":\"navigation-in-time\",\"scenario\":null,\"scenarios\":[],\"value\":null,"
                + "\"battery\":null,\"pairs\":2,\"rule\":\"forecast\",\"clause\":\"deadline\",\"reason\":\"pending\","
                + "\"forecast\":null,\"deadline\":{\"probability\":null,\"timeLeft\":57.0,\"atRisk\":0,\"longer\":0,"
                + "\"novel\":true},\"wallTime\":\"2026-11-25T17:40:01.123Z\"}", EventJson.line(EventJson.of(w, null, AT)));
        MonitorEvent.Recovered r = new MonitorEvent.Recovered(352, 7415, "discharged", Double.NaN, "in time",
                Clock.TICKS, 0, "navigation-in-time");
        assertEquals("{\"event\":\"recovered\",\"time\":352.0,\"unit\":\"ticks\",\"line\":7415,\"run\":0,"
                + "\"cause\":\"discharged\",\"value\":null,\"battery\":null,\"reason\":\"in time\","
                + "\"property\":\"navigation-in-time\",\"wallTime\":\"2026-11-25T17:40:01.123Z\"}",
                EventJson.line(EventJson.of(r, null, AT)));
    }

    @Test
    void aLogEventsLineIsItsJsonNamingTheLog() {
        LogEvent sent = LogEvent.of("a.log", new MonitorEvent.NoMatch(5, 40, Clock.SECONDS, 0), AT);
        assertEquals("{\"event\":\"no-match\",\"log\":\"a.log\",\"time\":5.0,\"unit\":\"s\",\"line\":40,\"run\":0,"
                + "\"wallTime\":\"2026-11-25T17:40:01.123Z\"}", sent.line());
        assertThrows(IllegalArgumentException.class, () -> EventJson.of(new MonitorEvent.Unmapped(1, 2,
                new UnmappedMessage("X", "y", UnmappedMessage.Kind.COMMAND, "")),
                null, AT), "an unmapped message goes to stderr, it is no JSON event");
    }
}
