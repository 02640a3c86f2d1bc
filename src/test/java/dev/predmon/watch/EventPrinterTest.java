package dev.predmon.watch;

import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.Clock;
import org.junit.jupiter.api.Test;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * The text lines of {@code watch} name the watched property's value by the property's id: a hand-written abstraction
 * that watches a motor's temperature reads {@code temperature 61.20}, the built-in one {@code battery 27.83}.
 */
class EventPrinterTest {

    private static EventPrinter printer() {
        return new EventPrinter(new PrintWriter(new StringWriter()), false, false, null, Stamp.NONE);
    }

    private static MonitorEvent.Warning warning(String property, double value) {
        return new MonitorEvent.Warning(29.582, 7127, List.of(), value, 12, Clock.SECONDS, 0, WarningRule.FORECAST,
                null, "P(violation) 0.90 reaches the warning threshold 0.86", MonitorEvent.Clause.FORECAST, null,
                property);
    }

    @Test
    void aTemperaturesWarningAndViolationNameTheTemperature() {
        EventPrinter p = printer();
        String warned = p.toText(warning("temperature", 61.2));
        String violated = p.toText(new MonitorEvent.Violation(34.6, 8219, "temperature", "motor temperature <= 70",
                70.4, 69.8, "70.4 above the ceiling 70", Clock.SECONDS, 0, true));
        assertEquals("t=29.582 line 7127: WARNING: P(violation) 0.90 reaches the warning threshold 0.86; "
                + "temperature 61.20", warned);
        assertEquals("t=34.600 line 8219: VIOLATION of 'motor temperature <= 70': 70.40; lead of the warning: "
                + "5.018 s, temperature 61.20 at the warning vs 70.40 now", violated);
        assertFalse((warned + violated).contains("battery"));
    }

    @Test
    void theBuiltInBatteryReadsAsBefore() {
        EventPrinter p = printer();
        assertEquals("t=29.582 line 7127: WARNING: P(violation) 0.90 reaches the warning threshold 0.86; "
                + "battery 27.83", p.toText(warning("battery", 27.83)));
        assertEquals("t=34.608 line 8219: VIOLATION of 'battery level >= 20%': 15.86; lead of the warning: 5.026 s, "
                + "battery 27.83 at the warning vs 15.86 now", p.toText(new MonitorEvent.Violation(34.608, 8219,
                "battery", "battery level >= 20%", 15.86, 20.18, null, Clock.SECONDS, 0, true)));
    }

    @Test
    void aWarningOfNoNamedPropertySaysValue() {
        assertEquals("t=29.582 line 7127: WARNING: P(violation) 0.90 reaches the warning threshold 0.86; "
                + "value unknown", printer().toText(new MonitorEvent.Warning(29.582, 7127, List.of(), null, 12,
                Clock.SECONDS, 0, WarningRule.FORECAST, null, "P(violation) 0.90 reaches the warning threshold 0.86",
                MonitorEvent.Clause.FORECAST, null, null)));
    }
}
