package dev.predmon.event;

import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;

/**
 * A forecast as JSON: {@code probability} (0 to 1), {@code timeToViolation} in the log's {@code unit} (null when no
 * violation is in sight, a probability below 0.005 included) with its interval {@code low}..{@code high} (null when open), what it rests on
 * ({@code basis}: matched, resynchronised, value only, violated), {@code novelSince} (the line from which the run did
 * something no model does, or null), the training {@code runs} behind it and how many {@code violated}, and the same
 * in words ({@code explanation}).
 */
public record ForecastJson(double probability, Double timeToViolation, Double low, Double high, String unit, String basis,
                    Long novelSince, int runs, int violated, Double value, Double drift, String explanation) {

    /** The JSON of {@code f}, or null for none. */
    public static ForecastJson of(Forecast f) {
        if (f == null) {
            return null;
        }
        // a probability that reads as 0 has no time to a violation beside it
        boolean inSight = ForecastWords.inSight(f);
        return new ForecastJson(round(f.probability()), inSight ? round(f.timeToViolation()) : null,
                inSight ? round(f.low()) : null, inSight ? round(f.high()) : null,
                f.unit(), f.basis().label(), f.novelSince(), f.runs(), f.violated(), round(f.value()),
                f.drift() == null ? null : Math.round(f.drift() * 1e6) / 1e6, ForecastWords.line(f));
    }

    private static Double round(Double x) {
        return x == null ? null : Math.round(x * 1e4) / 1e4;
    }
}
