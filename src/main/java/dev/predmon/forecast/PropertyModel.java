package dev.predmon.forecast;

import java.util.List;

/**
 * What the forecast learned for one property, by its kind: a bound's value forecast (the abstraction's first floor
 * among them, as any other bound), a bounded response's deadline forecast, an absence's or a precedence's event
 * forecast. {@code forecast.json} holds one per property ({@link ForecastFile}); {@link ForecastModel#property}
 * gives it in memory.
 *
 * <p>A new forecast kind is one more record here, its entry in {@link PropertyCodec} (how the file writes and reads
 * it) and where {@link PropertyModels} keeps it in a {@link ForecastModel}.
 */
public sealed interface PropertyModel permits PropertyModel.OfBound, PropertyModel.OfDeadline, PropertyModel.OfEvent {

    /** The property's id in the abstraction. */
    String id();

    /** How well its rule did in the cross-validation, beside its baseline's (empty when it was not scored). */
    List<Scorecard> scorecards();

    /**
     * The value forecast of a bound with a floor or a ceiling.
     *
     * @param model its forecast and the side it forecasts (the first floor's side is {@link BoundModel#FLOOR})
     */
    record OfBound(String id, BoundModel model) implements PropertyModel {

        @Override
        public List<Scorecard> scorecards() {
            return model.model().scorecards();
        }
    }

    /**
     * The deadline forecast of a bounded response.
     *
     * @param obligations how long its obligations stayed pending in the training runs (empty when none was opened)
     * @param rule        when its forecast warns, or null when none was learned ({@link DeadlineRule#DEFAULT} warns)
     * @param scorecards  its scorecard, when held-out obligations missed their deadline
     */
    record OfDeadline(String id, Survival obligations, DeadlineRule rule, List<Scorecard> scorecards)
            implements PropertyModel {

        public OfDeadline {
            scorecards = List.copyOf(scorecards);
        }

        /** The rule it warns by: its own, else the default. */
        public DeadlineRule warnsBy() {
            return rule == null ? DeadlineRule.DEFAULT : rule;
        }
    }

    /**
     * The event forecast of an absence or a precedence, or why the training runs give none.
     *
     * @param model its forecast or its counts
     */
    record OfEvent(String id, EventModel model) implements PropertyModel {

        @Override
        public List<Scorecard> scorecards() {
            return model.scorecards();
        }
    }
}
