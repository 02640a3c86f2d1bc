package dev.predmon.forecast;

import java.util.Map;
import java.util.TreeMap;

/**
 * Reads {@code forecast.json} of format 1, as models learned before format 2 hold it: the first floor's forecast at
 * the top level, the other properties in side maps ({@code obligations} with the deadline rules, {@code bounds},
 * {@code events}), and the scorecards of the first floor and the deadlines in one list. Its properties are not named
 * (the file does not say which property the top level forecasts): {@link PropertyParts#named} names them with the
 * abstraction the models were learned with.
 */
final class ForecastFileOne {

    private ForecastFileOne() {
    }

    static ForecastModel read(JsonAt root) {
        String unit = root.text("unit");
        ForecastModel m = ForecastFileSections.readBody(root, ForecastModel.FORMAT_1, unit);
        Map<String, Survival> obligations = new TreeMap<>();
        Map<String, DeadlineRule> rules = new TreeMap<>();
        JsonAt o = root.optional("obligations");
        if (o != null) {
            for (Map.Entry<String, JsonAt> e : o.members().entrySet()) {
                obligations.put(e.getKey(), ForecastFileSections.readSurvival(e.getValue()));
                DeadlineRule rule = ForecastFileSections.readRule(e.getValue());
                if (rule != null) {
                    rules.put(e.getKey(), rule);
                }
            }
        }
        Map<String, BoundModel> bounds = new TreeMap<>();
        JsonAt b = root.optional("bounds");
        if (b != null) {
            for (Map.Entry<String, JsonAt> e : b.members().entrySet()) {
                JsonAt at = e.getValue().object();
                String side = at.text("side");
                ForecastModel own = ForecastFileSections.readBody(at, ForecastModel.FORMAT_1, unit);
                bounds.put(e.getKey(), at.get("side").built(() -> new BoundModel(side, own)));
            }
        }
        Map<String, EventModel> events = new TreeMap<>();
        JsonAt ev = root.optional("events");
        if (ev != null) {
            for (Map.Entry<String, JsonAt> e : ev.members().entrySet()) {
                events.put(e.getKey(), PropertyCodec.event(e.getValue().object(), ForecastModel.FORMAT_1, unit));
            }
        }
        return m.withObligations(obligations).withDeadlines(rules).withBounds(bounds).withEvents(events);
    }
}
