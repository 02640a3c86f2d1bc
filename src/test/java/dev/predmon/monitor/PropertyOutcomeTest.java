package dev.predmon.monitor;

import dev.predmon.parse.Clock;
import dev.predmon.property.Absence;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker.PropertyVerdict;
import dev.predmon.property.Scope;
import dev.predmon.property.Verdict;
import org.junit.jupiter.api.Test;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** A run's outcome per property, worst first, by hand-computed cases. */
class PropertyOutcomeTest {

    private static Property property(String id) {
        return new Absence(id, id + " in words", null, Scope.GLOBAL, null);
    }

    private static MonitorEvent.Warning warning(String id, long line, double time) {
        return new MonitorEvent.Warning(time, line, List.of(), null, 3, Clock.SECONDS, 0, WarningRule.FORECAST, null,
                "why", MonitorEvent.Clause.DEADLINE, null, id);
    }

    private static RunOutcome run(boolean batteryRead, Map<String, MonitorEvent.Warning> warnings,
                                  PropertyVerdict... verdicts) {
        return new RunOutcome(0, 1, null, null, false, 7, batteryRead, null, List.of(verdicts),
                warnings.values().stream().findFirst().orElse(null), warnings);
    }

    @Test
    void violatedThenWarnedThenOpenThenHoldsEachInTheAbstractionsOrder() {
        Map<String, MonitorEvent.Warning> warned = new LinkedHashMap<>();
        warned.put("nav", warning("nav", 50, 5.0));
        warned.put("grasp", warning("grasp", 60, 6.0)); // after the grasp's violation at line 55: predicts nothing
        warned.put("abort", warning("abort", 20, 2.0));
        RunOutcome r = run(true, warned,
                new PropertyVerdict(property("battery"), Verdict.HOLDS),
                new PropertyVerdict(property("pending"), new Verdict.Pending(10, 1, 9, dev.predmon.property.Deadline
                        .Unit.TICKS)),
                new PropertyVerdict(property("nav"), Verdict.HOLDS),
                new PropertyVerdict(property("grasp"), new Verdict.Violated(55, 5.5, null, null, "8 attempts")),
                new PropertyVerdict(property("abort"), new Verdict.Violated(30, 3.5, null, null, "aborted")),
                new PropertyVerdict(property("quiet"), Verdict.HOLDS));
        List<PropertyOutcome> o = PropertyOutcome.of(r, "battery");
        assertEquals(List.of("grasp", "abort", "nav", "pending", "battery", "quiet"),
                o.stream().map(PropertyOutcome::id).toList());
        assertEquals(List.of("violated", "violated", "warned", "pending", "holds", "holds"),
                o.stream().map(PropertyOutcome::state).toList());
        assertEquals("grasp VIOLATED with no warning before it; abort VIOLATED, warned 1.5 s before; nav warned; "
                + "pending pending; battery, quiet hold", PropertyOutcome.sentence(o, true, l -> l + " s"));
        assertEquals("abort VIOLATED at line 30, warned 1.5 s before (line 20): aborted",
                o.get(1).words(l -> l + " s"));
        assertEquals(List.of("grasp", "abort"), r.violatedProperties());
        assertEquals(List.of("nav", "grasp", "abort"), r.warnedProperties());
    }

    @Test
    void aBatteryNeverReadIsNotObservedAndNothingWarnedSaysSo() {
        RunOutcome r = run(false, Map.of(), new PropertyVerdict(property("battery"), Verdict.HOLDS),
                new PropertyVerdict(property("abort"), Verdict.HOLDS));
        List<PropertyOutcome> o = PropertyOutcome.of(r, "battery");
        assertEquals("no warning; battery not observed; abort holds", PropertyOutcome.sentence(o, false, l -> ""));
        assertEquals("warning raised", PropertyOutcome.sentence(List.of(), true, l -> ""),
                "an abstraction with no property says whether the run was warned");
    }

    @Test
    void aVerdictThisCodeDoesNotKnowIsNeverAsGoodAsHolds() {
        assertEquals(PropertyOutcome.OPEN, PropertyOutcome.rank("no-evidence"));
        assertEquals(PropertyOutcome.OPEN, PropertyOutcome.rank("pending"));
        assertEquals(PropertyOutcome.HOLDS, PropertyOutcome.rank("holds"));
        assertEquals(PropertyOutcome.VIOLATED, PropertyOutcome.rank("violated"));
    }

    @Test
    void severalRunsGiveEachPropertysWorst() {
        RunOutcome first = run(true, Map.of(), new PropertyVerdict(property("battery"), new Verdict.Violated(9, 9,
                18.0, 21.0, "18 below 20")), new PropertyVerdict(property("abort"), Verdict.HOLDS));
        RunOutcome second = run(true, Map.of("abort", warning("abort", 3, 3)),
                new PropertyVerdict(property("battery"), Verdict.HOLDS), new PropertyVerdict(property("abort"),
                        Verdict.HOLDS));
        List<PropertyOutcome> both = PropertyOutcome.worstOver(List.of(PropertyOutcome.of(first, "battery"),
                PropertyOutcome.of(second, "battery")));
        assertEquals("battery VIOLATED with no warning before it; abort warned",
                PropertyOutcome.sentence(both, true, l -> ""));
    }
}
