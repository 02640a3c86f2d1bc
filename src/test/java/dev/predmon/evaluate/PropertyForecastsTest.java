package dev.predmon.evaluate;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.Survival;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.parse.Clock;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/** Each property's forecasts read from a run's events, each with its own outcome. */
class PropertyForecastsTest {

    private static final Abstraction A = AbstractionFiles.defaults();

    private static MonitorEvent deadline(double time, double p, double left) {
        Survival.Estimate e = Double.isNaN(p) ? new Survival.Estimate(Double.NaN, left, 0, 0, true)
                : new Survival.Estimate(p, left, 5, 1, false);
        return new MonitorEvent.ForecastChanged(time, (long) time, null, Clock.TICKS, 0, "navigation-in-time", e,
                "ticks");
    }

    private static MonitorEvent violation(double time, String property) {
        return new MonitorEvent.Violation(time, (long) time, property, property, null, null, "late", Clock.TICKS, 0,
                false);
    }

    /**
     * Two navigations: the first discharged in time (its forecasts score 0), the second missed its deadline (1). A
     * forecast past every training obligation has no probability; forecasts after the violation are not scored.
     */
    @Test
    void aDeadlineForecastIsScoredAgainstItsOwnObligation() {
        List<MonitorEvent> events = List.of(deadline(1, 0.1, 400), deadline(50, 0.2, 351), deadline(200, 0.3, 400),
                deadline(300, 0.6, 300), deadline(450, Double.NaN, 150), violation(601, "navigation-in-time"),
                deadline(700, 0.1, 400));
        PropertyForecasts f = PropertyForecasts.of(events, A, null, Map.of()).get("navigation-in-time");
        assertEquals(RunResult.PropertyResult.OBLIGATION, f.scope());
        assertEquals(List.of(0.1, 0.2, 0.3, 0.6), f.run().probabilities());
        assertEquals(List.of(0, 0, 1, 1), f.run().outcomes());
    }

    @Test
    void inARunThatHeldEveryObligationScoresZero() {
        List<MonitorEvent> events = List.of(deadline(1, 0.4, 400), deadline(30, 0.7, 370), deadline(90, 0.2, 400));
        PropertyForecasts f = PropertyForecasts.of(events, A, null, Map.of()).get("navigation-in-time");
        assertEquals(List.of(0, 0, 0), f.run().outcomes());
        assertFalse(PropertyForecasts.of(events, A, null, Map.of()).containsKey("no-abort"),
                "a property with no forecast event has no forecast");
    }

    /** A value forecast of any property other than the forecast's: P(the run violates it), scored per run. */
    @Test
    void aValueForecastIsScoredAgainstTheRunsOutcomeWithTheTrainingRunsShare() {
        Forecast low = new Forecast(0.2, null, null, null, Forecast.Basis.VALUE_ONLY, null, 4, 1, 30.0, null, "s");
        Forecast high = new Forecast(0.7, null, null, null, Forecast.Basis.VALUE_ONLY, null, 4, 3, 25.0, null, "s");
        List<MonitorEvent> events = List.of(
                new MonitorEvent.ForecastChanged(1, 1, low, Clock.SECONDS, 0, "no-abort"),
                new MonitorEvent.ForecastChanged(2, 2, high, Clock.SECONDS, 0, "no-abort"),
                new MonitorEvent.ForecastChanged(3, 3, low, Clock.SECONDS, 0, "battery"),
                violation(4, "no-abort"));
        Map<String, PropertyForecasts> all = PropertyForecasts.of(events, A, null, Map.of("no-abort", 0.25));
        PropertyForecasts f = all.get("no-abort");
        assertEquals(RunResult.PropertyResult.RUN, f.scope());
        assertEquals(List.of(0.2, 0.7), f.run().probabilities());
        assertEquals(List.of(1, 1), f.run().outcomes());
        assertEquals(0.25, f.run().baseRate());
        assertFalse(all.containsKey("battery"), "the forecast's own property is scored by ForecastScore");
    }
}
