package dev.predmon.monitor;

import dev.predmon.forecast.Forecast;

/**
 * Told every value forecast of a bound property, as the property reads, one per pair and per new value of it while
 * its scope is open: the stream of the held-out replays ({@link PredictiveMonitor#onEveryBoundForecast}).
 */
@FunctionalInterface
public interface BoundSteps {
    /** A forecast of {@code property} in run {@code run}. */
    void forecast(String property, Forecast f, int run);
}
