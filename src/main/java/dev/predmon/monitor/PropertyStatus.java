package dev.predmon.monitor;

import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.Survival;
import dev.predmon.property.Property;
import dev.predmon.property.Verdict;

/**
 * One property of the run being watched, now: its verdict, whether a warning of it is up, and its latest forecast.
 *
 * @param property the property
 * @param verdict  its verdict on the run so far
 * @param model    what forecasts it
 * @param warned   whether a warning of it is up now (raised, and neither recovered from nor overtaken by a violation)
 * @param deadline for {@link Model#DEADLINE}, the forecast of the obligation pending now, or null when none is
 * @param unit     for {@link Model#DEADLINE}, what the deadline and {@code deadline}'s time left count
 *                 ({@code ticks}, {@code seconds}, {@code occurrences}); else null
 * @param forecast for {@link Model#FORECAST}, its latest value forecast (the monitor's own for the forecast's
 *                 property, a bound property's own for any other), null before one and for the other models
 * @param noForecast for {@link Model#NONE}, why the training runs gave the property no forecast, in words
 *                   ({@code never violated in 43 training runs}); null when no model of it was learned at all
 */
public record PropertyStatus(Property property, Verdict verdict, Model model, boolean warned,
                             Survival.Estimate deadline, String unit, Forecast forecast, String noForecast) {

    /** A status that is not told why it has no forecast. */
    public PropertyStatus(Property property, Verdict verdict, Model model, boolean warned, Survival.Estimate deadline,
                          String unit, Forecast forecast) {
        this(property, verdict, model, warned, deadline, unit, forecast, null);
    }

    /** Why there is no forecast, in words: {@code no forecast: never violated in 43 training runs}. */
    public String noForecastWords() {
        return "no forecast: " + (noForecast == null ? "no model of this property" : noForecast);
    }

    /** A status without a value forecast of its own. */
    public PropertyStatus(Property property, Verdict verdict, Model model, boolean warned, Survival.Estimate deadline,
                          String unit) {
        this(property, verdict, model, warned, deadline, unit, null);
    }

    /** What forecasts a property. */
    public enum Model {
        /**
         * A value forecast ({@code ForecastTracker}): the run's forecast of the forecast's property, a bound
         * property's own ({@code BoundFollow}), or an absence's or a precedence's ({@code EventFollow}); a
         * probability of violation and a time to it.
         */
        FORECAST,
        /** A bounded response's deadline forecast from the training runs' obligations ({@code DeadlineFollow}). */
        DEADLINE,
        /** Nothing: no model of the property (an absence, a precedence, a response the training runs never owed). */
        NONE;

        /** As in JSON: {@code forecast}, {@code deadline}, {@code none}. */
        public String id() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }
}
