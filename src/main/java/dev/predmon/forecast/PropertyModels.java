package dev.predmon.forecast;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * A {@link ForecastModel} as one {@link PropertyModel} per property, and back: where each kind is kept in the model.
 * The first floor is kept at the model's top level (what the matching, the evaluation and the live page read of it),
 * the other properties by id in one map per kind; seen per property, the first floor is a bound like any other.
 */
final class PropertyModels {

    /** The note of a model whose abstraction has no first floor: nothing is forecast by value at its top level. */
    static final String NO_FIRST_FLOOR = "no first floor: the abstraction has no bound with a floor";

    private PropertyModels() {
    }

    /** Every property of {@code m}, in its order ({@link ForecastModel#properties}). */
    static List<PropertyModel> of(ForecastModel m) {
        Map<String, PropertyModel> byId = new TreeMap<>();
        if (m.first() != null) {
            put(byId, new PropertyModel.OfBound(m.first(), new BoundModel(BoundModel.FLOOR, own(m))));
        }
        m.bounds().forEach((id, b) -> put(byId, new PropertyModel.OfBound(id, new BoundModel(b.side(),
                own(b.model())))));
        TreeSet<String> deadlines = new TreeSet<>(m.obligations().keySet());
        deadlines.addAll(m.deadlines().keySet());
        deadlines.addAll(m.deadlineCards().keySet());
        for (String id : deadlines) {
            put(byId, new PropertyModel.OfDeadline(id, m.obligations().getOrDefault(id, new Survival(new double[0], new double[0])),
                    m.deadlines().get(id), m.deadlineCards().getOrDefault(id, List.of())));
        }
        m.events().forEach((id, e) -> put(byId, new PropertyModel.OfEvent(id, e.forecasts() ? e.with(own(e.model()))
                : e)));
        Map<String, PropertyModel> ordered = new LinkedHashMap<>();
        m.order().stream().filter(byId::containsKey).forEach(id -> ordered.put(id, byId.get(id)));
        if (m.first() != null) {
            ordered.putIfAbsent(m.first(), byId.get(m.first()));
        }
        byId.forEach(ordered::putIfAbsent);
        return List.copyOf(ordered.values());
    }

    private static void put(Map<String, PropertyModel> byId, PropertyModel p) {
        if (byId.putIfAbsent(p.id(), p) != null) {
            throw new IllegalArgumentException("property '" + p.id() + "' has forecasts of two kinds");
        }
    }

    /** {@code m}'s own forecast, without the other properties' it carries. */
    private static ForecastModel own(ForecastModel m) {
        return new ForecastModel(m.format(), m.unit(), m.limit(), m.runs(), m.violating(), m.lows(), m.threshold(),
                m.thresholdNote(), m.validated(), m.states(), m.startInputs(), m.calibration(), m.scorecards(),
                Map.of(), Map.of(), Map.of(), m.clauses(), Map.of(), Map.of(), null, List.of());
    }

    /**
     * The model of {@code properties}, in the abstraction's order, over {@code runs} training runs in {@code unit}.
     * The first bound forecast on its floor is the first floor, as the abstraction's first bound with a floor is (a
     * bound before it has no floor, so it is forecast on its ceiling). Without one, the top level forecasts nothing
     * ({@link #NO_FIRST_FLOOR}).
     *
     * @throws IllegalArgumentException when two of them are of the same property
     */
    static ForecastModel assemble(String unit, int runs, List<PropertyModel> properties) {
        PropertyModel.OfBound head = null;
        Map<String, BoundModel> bounds = new TreeMap<>();
        Map<String, Survival> obligations = new TreeMap<>();
        Map<String, DeadlineRule> rules = new TreeMap<>();
        Map<String, List<Scorecard>> cards = new TreeMap<>();
        Map<String, EventModel> events = new TreeMap<>();
        List<String> order = new ArrayList<>();
        for (PropertyModel p : properties) {
            if (order.contains(p.id())) {
                throw new IllegalArgumentException("property '" + p.id() + "' has two forecasts");
            }
            order.add(p.id());
            if (p instanceof PropertyModel.OfBound b) {
                if (head == null && !b.model().mirrored()) {
                    head = b;
                } else {
                    bounds.put(b.id(), new BoundModel(b.model().side(), own(b.model().model())));
                }
            } else if (p instanceof PropertyModel.OfDeadline d) {
                obligations.put(d.id(), d.obligations());
                if (d.rule() != null) {
                    rules.put(d.id(), d.rule());
                }
                if (!d.scorecards().isEmpty()) {
                    cards.put(d.id(), d.scorecards());
                }
            } else if (p instanceof PropertyModel.OfEvent e) {
                events.put(e.id(), e.model().forecasts() ? e.model().with(own(e.model().model())) : e.model());
            }
        }
        ForecastModel t = head == null ? headless(unit, runs) : head.model().model();
        return new ForecastModel(ForecastModel.FORMAT, unit, t.limit(), t.runs(), t.violating(), t.lows(),
                t.threshold(), t.thresholdNote(), t.validated(), t.states(), t.startInputs(), t.calibration(),
                t.scorecards(), obligations, rules, bounds, t.clauses(), events, cards,
                head == null ? null : head.id(), order);
    }

    /**
     * The top level of a model without a first floor: {@code runs} training runs, none violating what no property
     * labels, no state, the default threshold unvalidated, and the thesis's matching not chosen by anything.
     */
    static ForecastModel headless(String unit, int runs) {
        return new ForecastModel(ForecastModel.FORMAT, unit, Double.NaN, runs, 0, new Lows(new double[0],
                new double[0]), ThresholdChoice.DEFAULT, NO_FIRST_FLOOR, false, Map.of(), List.of(),
                Calibration.IDENTITY, List.of(), Map.of(), Map.of(), Map.of(), Clauses.NO_MATCHING, Map.of(),
                Map.of(), null, List.of());
    }
}
