package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.matching.Matching;
import dev.predmon.model.ModelIndex;
import dev.predmon.model.ModelSet;
import dev.predmon.pipeline.TriggerInputs;
import dev.predmon.property.Property;

import java.util.HashMap;
import java.util.Map;
import java.util.function.Consumer;

/**
 * What the {@link PredictiveMonitor} says of the properties other than its forecast's, wired together: every property
 * checked by the {@link SafetyMonitor}; under the forecast rule, each bounded response's deadline forecast ({@link
 * DeadlineWatch}, told by {@link DeadlineEvents}) and each other bound property's value forecast ({@link BoundWatch},
 * which follows the pairs with the {@link ForecastFollow}); and, by faulty scenario, the property its matching warning
 * is about ({@code violates}). The replay's listeners of those forecasts are set here.
 */
final class OtherForecasts {

    private final SafetyMonitor properties;
    private final DeadlineEvents deadlines;
    /** The other bound properties' value forecasts, or null under the match rule. */
    private final BoundWatch bounds;
    private final Map<String, Property> violates;

    OtherForecasts(ModelSet models, Abstraction abstraction, WarningRule rule, Matching matching, RunState now,
                   Consumer<MonitorEvent> events) {
        boolean forecasts = rule == WarningRule.FORECAST;
        this.deadlines = new DeadlineEvents(now, rule, events);
        this.properties = new SafetyMonitor(abstraction, events, forecasts
                ? new DeadlineWatch(abstraction.properties(), models.forecast(),
                new TriggerInputs(abstraction, abstraction.properties())) : null, deadlines);
        // the other bound properties' forecasts warn by the same rule
        this.bounds = forecasts ? properties.forecastBounds(new BoundWatch(abstraction.properties(), models, rule, now,
                events), () -> !matching.nominalAlive()) : null;
        this.violates = violates(models, abstraction);
    }

    /** Every property's check, with the deadline and bound forecasts. */
    SafetyMonitor properties() {
        return properties;
    }

    /**
     * By faulty scenario, the property its runs violate, of the scenarios whose {@code scenario.json} names one of the
     * abstraction's properties ({@link ForecastFollow}'s {@code violates}).
     */
    Map<String, Property> violates() {
        return violates;
    }

    /** Lets the other bound properties' forecasts follow the pairs with {@code follow}. */
    void followedBy(ForecastFollow follow) {
        if (bounds != null) {
            follow.forecastBounds(bounds);
        }
    }

    /** As {@link PredictiveMonitor#onEveryDeadlineForecast}. */
    void onEveryDeadlineForecast(DeadlineSteps each) {
        deadlines.steps(each);
    }

    /** As {@link PredictiveMonitor#onEveryBoundForecast}. */
    void onEveryBoundForecast(BoundWatch.Every each) {
        if (bounds != null) {
            bounds.onEveryForecast(each);
        }
    }

    private static Map<String, Property> violates(ModelSet models, Abstraction abstraction) {
        Map<String, Property> out = new HashMap<>();
        for (ModelIndex.Scenario s : models.index().scenarios()) {
            if (s.faulty() && s.violates() != null) {
                abstraction.properties().stream().filter(p -> p.id().equals(s.violates())).findFirst()
                        .ifPresent(p -> out.put(s.name(), p));
            }
        }
        return out;
    }
}
