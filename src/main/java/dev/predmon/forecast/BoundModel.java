package dev.predmon.forecast;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The value forecast of one bound property (the abstraction's first floor is one, kept at the top level of the
 * {@link ForecastModel} of every property; {@link #of} finds either): a {@link ForecastModel} of
 * its own (per-state statistics over the runs labelled by its violation, lows, threshold, calibration, scorecard),
 * and the side of the bound it forecasts.
 *
 * <p>One forecaster serves floors and ceilings: a ceiling is forecast as a floor of the mirrored value ({@code v}
 * read as {@code -v}, the ceiling {@code c} as the floor {@code -c}), so that "falls towards the floor" and its drift,
 * lows and time to violation mean the same on both sides. The model's numbers (its {@code limit}, its lows, its
 * states' drifts) are on that mirrored scale; {@link #value} and {@link #shown} turn a value and a forecast from and to
 * the property's own.
 *
 * @param side  {@link #FLOOR} or {@link #CEILING}: which bound is forecast (a bound with both is forecast on the side
 *              more of its violating training runs crossed first, the floor on a tie)
 * @param model the forecast, on the mirrored scale for a ceiling
 */
public record BoundModel(String side, ForecastModel model) {

    /** The side of a floor. */
    public static final String FLOOR = "floor";
    /** The side of a ceiling: its values are mirrored. */
    public static final String CEILING = "ceiling";

    public BoundModel {
        if (!FLOOR.equals(side) && !CEILING.equals(side)) {
            throw new IllegalArgumentException("side '" + side + "': expected " + FLOOR + " or " + CEILING);
        }
    }

    /**
     * The value forecast {@code forecast} holds for bound property {@code id}, or null (none, or no forecast): the
     * first floor's is its top level, forecast on the floor ({@code firstFloor}, the abstraction's {@link
     * Abstraction#safety}, which names it in a model not yet named by {@link ForecastModel#first}), every other
     * bound's is among its {@link ForecastModel#bounds}. One way to every bound's forecast, the first floor's too.
     */
    public static BoundModel of(ForecastModel forecast, String id, String firstFloor) {
        if (forecast == null) {
            return null;
        }
        return id != null && id.equals(firstFloor) ? new BoundModel(FLOOR, forecast) : forecast.bounds().get(id);
    }

    /** Every bound property of {@code abstraction} that {@code forecast} has a value forecast of, by id, in its order. */
    public static Map<String, BoundModel> all(ForecastModel forecast, Abstraction abstraction) {
        String first = abstraction.safety().map(Bound::id).orElse(null);
        Map<String, BoundModel> out = new LinkedHashMap<>();
        for (Property p : abstraction.properties()) {
            BoundModel m = p instanceof Bound ? of(forecast, p.id(), first) : null;
            if (m != null) {
                out.put(p.id(), m);
            }
        }
        return out;
    }

    /** Whether the values are mirrored (a ceiling). */
    public boolean mirrored() {
        return CEILING.equals(side);
    }

    /** {@code v} of the property on the forecast's scale: itself for a floor, {@code -v} for a ceiling. */
    public double value(double v) {
        return mirrored() ? -v : v;
    }

    /** The bound the forecast predicts the crossing of, on the forecast's scale. */
    public static double limit(Bound b, String side) {
        return CEILING.equals(side) ? -b.ceiling() : b.floor();
    }

    /**
     * {@code f} as the property reads: its value and drift mirrored back for a ceiling (the probability and the
     * times are the same on both scales).
     */
    public Forecast shown(Forecast f) {
        if (f == null || !mirrored()) {
            return f;
        }
        return new Forecast(f.probability(), f.timeToViolation(), f.low(), f.high(), f.basis(),
                f.novelSince(), f.runs(), f.violated(), f.value() == null ? null : -f.value(),
                f.drift() == null ? null : -f.drift(), f.unit());
    }
}
