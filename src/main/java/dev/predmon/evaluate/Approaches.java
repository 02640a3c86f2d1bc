package dev.predmon.evaluate;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.BoundModel;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyView;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * What the verdicts of a replay need of each record beyond the monitor's events: when each run began, and how each
 * bound property approached its violation with its raw-value baseline ({@link Approach}). Every bound that has a
 * value forecast is followed through the same map of forecasts ({@link BoundModel#all}), the first floor as any
 * other; a bound without a forecast is followed only when it is the first floor, whose readings near the bound a
 * run's result counts ({@link RunResult#sudden}).
 */
public final class Approaches {

    private static final Approach NONE = new Approach(null, Double.NaN, false);

    private final Map<Integer, Double> start = new HashMap<>();
    private final Map<String, Approach> bounds;

    private Approaches(Map<String, Approach> bounds) {
        this.bounds = bounds;
    }

    /** The approaches of {@code abstraction}'s bound properties, against the raw-value baselines of {@code models}. */
    public static Approaches of(ModelSet models, Abstraction abstraction) {
        Map<String, BoundModel> forecasts = BoundModel.all(models.forecast(), abstraction);
        Map<String, Approach> bounds = new LinkedHashMap<>();
        for (Property p : abstraction.properties()) {
            BoundModel m = forecasts.get(p.id());
            if (p instanceof Bound b && m != null) {
                bounds.put(p.id(), new Approach(b, m.model().lows().safeFloor(), m.mirrored()));
            }
        }
        abstraction.safety().ifPresent(b -> bounds.putIfAbsent(b.id(), new Approach(b, Double.NaN, false)));
        return new Approaches(bounds);
    }

    /** Takes record {@code r} of run {@code run}, after the monitor took it and judged it as {@code judged}. */
    public void record(LogRecord r, int run, PropertyView judged) {
        start.putIfAbsent(run, r.time());
        bounds.values().forEach(a -> a.record(r, run, judged));
    }

    /** The time of run {@code run}'s first record (0 before it). */
    double start(int run) {
        return start.getOrDefault(run, 0.0);
    }

    /** The approach of bound property {@code id}; one that never nears nor goes below for a property not followed. */
    Approach of(String id) {
        return id == null ? NONE : bounds.getOrDefault(id, NONE);
    }

    /** Every bound followed, by id, in the abstraction's order. */
    Map<String, Approach> all() {
        return bounds;
    }
}
