package dev.predmon.forecast;

import dev.predmon.property.Bound;

/**
 * The value forecast of one bound property other than the abstraction's safety property: a {@link ForecastModel} of
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
