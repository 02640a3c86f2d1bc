package dev.predmon.evaluate;

import dev.predmon.parse.LogRecord;
import dev.predmon.property.Bound;
import dev.predmon.property.PropertyView;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/**
 * One bound property's value as a run approaches its violation, per run: when the raw-value baseline warned (below
 * the lowest value a safe training run read) and the readings near the bound on the way to its violation (since the
 * value was last above the band), seen after the monitor took each record (so that {@code PredictiveMonitor#run()}
 * already counts a record that starts a run). The value and the violation are the monitor's checker's ({@link
 * PropertyView}: the reading within the property's scope, and whether it is violated now), so the violation counted
 * up to is the one it reported. Every bound is followed so, the first floor as any other ({@link Approaches}).
 */
public final class Approach {
    private final Bound rule;
    private int index = -1;
    /** The lowest value a safe training run read: the raw-value baseline warns below it (NaN: never). */
    private final double floor;
    /** Per run, when the value first went below the floor, and when the current stretch below it began. */
    private final Map<Integer, Double> firstBelow = new HashMap<>();
    private final Map<Integer, Double> below = new HashMap<>();
    private final Map<Integer, Double> belowAtViolation = new HashMap<>();
    private final Map<Integer, Integer> near = new HashMap<>();
    private final Set<Integer> violated = new HashSet<>();

    /** Whether the value is read mirrored (a ceiling's, whose floor is on the mirrored scale). */
    private final boolean mirrored;

    /**
     * @param rule     the bound followed, or null for none (nothing is below, nothing near)
     * @param floor    the raw-value baseline's: the lowest value a safe training run read (NaN: never)
     * @param mirrored whether the value is read {@code -v} (a ceiling forecast as a floor; {@code floor} is then
     *                 on that scale)
     */
    Approach(Bound rule, double floor, boolean mirrored) {
        this.rule = rule;
        this.floor = floor;
        this.mirrored = mirrored;
    }

    /** Takes record {@code r} of run {@code run}, after the monitor took it and judged it as {@code judged}. */
    void record(LogRecord r, int run, PropertyView judged) {
        if (rule == null || violated.contains(run)) {
            return;
        }
        index = index < 0 ? judged.indexOf(rule.id()) : index;
        double v = mirrored ? -judged.reading(index) : judged.reading(index);
        if (Double.isNaN(v)) {
            return;
        }
        if (judged.violatedNow(index)) {
            violated.add(run);
            Double stretch = below.get(run);
            if (stretch != null) {
                belowAtViolation.put(run, stretch);
            }
            return;
        }
        if (v < floor) {
            firstBelow.putIfAbsent(run, r.time());
            below.putIfAbsent(run, r.time());
        } else {
            below.remove(run); // the baseline's alarm ends when its cause ends, as the monitor's do
        }
        if (v < rule.floor() + RunResult.APPROACH_BAND) {
            near.merge(run, 1, Integer::sum);
        } else {
            // Back above the band: an earlier dip that recovered (a recharge) is no approach to a later violation.
            near.remove(run);
        }
    }

    /**
     * When the raw-value baseline warned run {@code run}, or null: for a violated run, the start of the stretch
     * below the floor that lasted until the violation (a dip that recovered earlier does not foresee it); for a
     * run that held, its first stretch (a false alarm).
     */
    Double belowFloor(int run) {
        return violated.contains(run) ? belowAtViolation.get(run) : firstBelow.get(run);
    }

    int near(int run) {
        return near.getOrDefault(run, 0);
    }
}
