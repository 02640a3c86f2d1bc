package dev.predmon.hooks;

import dev.predmon.forecast.Survival;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.Clock;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** A deadline's warning gives the robot its property and its probability of a miss, or none past every training one. */
class DeadlineHookTest {

    private static MonitorEvent.Warning warning(Survival.Estimate e) {
        return new MonitorEvent.Warning(120, 3500, List.of(), null, 40, Clock.TICKS, 0, WarningRule.FORECAST, null,
                "pending", MonitorEvent.Clause.DEADLINE, null, "navigation-in-time", e);
    }

    @Test
    void theProbabilityOfAMissOrNoneWhenNeverSeen() {
        Map<String, String> env = HookEnvironment.of("r1.log", warning(new Survival.Estimate(0.6249, 20, 5, 2, false)));
        assertEquals("navigation-in-time", env.get("PREDMON_PROPERTY"));
        assertEquals("0.62", env.get("PREDMON_PROBABILITY"));
        assertEquals("", env.get("PREDMON_VALUE"), "a bounded response has no value");
        assertEquals("", env.get("PREDMON_BATTERY"));
        Map<String, String> novel = HookEnvironment.of("r1.log",
                warning(new Survival.Estimate(Double.NaN, 66, 0, 0, true)));
        assertEquals("", novel.get("PREDMON_PROBABILITY"), "no evidence, no number");
    }

    @Test
    void aRecoveryNamesItsPropertyAndItsCause() {
        Map<String, String> env = HookEnvironment.of("r1.log", new MonitorEvent.Recovered(352, 7415, "discharged",
                Double.NaN, "the response came in time", Clock.TICKS, 0, "navigation-in-time"));
        assertEquals("recovered", env.get("PREDMON_EVENT"));
        assertEquals("navigation-in-time", env.get("PREDMON_PROPERTY"));
        assertEquals("discharged", env.get("PREDMON_CAUSE"));
        assertEquals("", env.get("PREDMON_VALUE"), "a bounded response has no value");
        assertEquals("7415", env.get("PREDMON_LINE"));
    }
}
