package dev.predmon.property;

import dev.predmon.parse.LogRecord;

import java.util.List;

/**
 * A numeric value stays within bounds: every reading is at least {@code floor} and at most {@code ceiling}
 * ({@code historically(floor <= v <= ceiling)}). The built-in battery property is a floor: {@code level >= 20}, the
 * thesis's SCXML monitor of Section 3.3.1 and SCOPE's {@code BatteryLevelMonitor}. A reply that is no number
 * ({@code NaN}, a word) reads nothing and violates nothing.
 *
 * @param floor    the least value that holds, or negative infinity for none
 * @param ceiling  the greatest value that holds, or positive infinity for none
 * @param underWay the messages that say the action is under way (advice, like the action; empty when none)
 */
public record Bound(String id, String name, String action, Scope scope, ValueReader value, double floor,
                    double ceiling, List<UnderWay> underWay) implements Property {

    public Bound {
        underWay = underWay == null ? List.of() : List.copyOf(underWay);
    }

    /** A bound without messages that say its action is under way. */
    public Bound(String id, String name, String action, Scope scope, ValueReader value, double floor,
                 double ceiling) {
        this(id, name, action, scope, value, floor, ceiling, List.of());
    }

    /** A floor on {@code value}, checked over the whole run. */
    public Bound(String id, String name, String action, ValueReader value, double floor) {
        this(id, name, action, Scope.GLOBAL, value, floor, Double.POSITIVE_INFINITY);
    }

    /** What the violating value {@code v} did, in words: {@code 18.5 below the floor 20}. */
    public String violation(double v) {
        return v < floor ? Numbers.text(v) + " below the floor " + Numbers.text(floor)
                : Numbers.text(v) + " above the ceiling " + Numbers.text(ceiling);
    }

    @Override
    public String kind() {
        return "bound";
    }

    /** The watched value carried by {@code r}, or NaN when {@code r} carries none. */
    public double valueOf(LogRecord r) {
        return value.valueOf(r);
    }

    /** Whether {@code v} (from {@link #valueOf}) violates the property. */
    public boolean violatedBy(double v) {
        return v < floor || v > ceiling;
    }

    /** Whether the property has a floor, the bound a value can fall to (what the forecast predicts). */
    public boolean hasFloor() {
        return floor != Double.NEGATIVE_INFINITY;
    }
}
