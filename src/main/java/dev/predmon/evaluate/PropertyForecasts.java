package dev.predmon.evaluate;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.Survival;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.property.Property;
import dev.predmon.property.Response;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * What the forecasts of one property other than the forecast's said in one run, read from the replay's events (the
 * {@link MonitorEvent.ForecastChanged} events that carry the property's id, up to its first violation), each forecast
 * with its outcome.
 *
 * <ul>
 *   <li>A deadline forecast (a bounded response's) is P(the pending obligation misses its deadline): its outcome is
 *       whether that obligation missed it. An obligation discharged in time, or still pending when the run ended,
 *       scores 0, even in a run that a later obligation violated. A forecast past every training obligation has no
 *       probability and is not scored. Its base rate is the models' share of training obligations that missed the
 *       deadline ({@link Survival#survival} at the deadline, censored runs counted as at risk as long as they
 *       lasted).</li>
 *   <li>A forecast of a value (a bound's) is P(the run violates the property): its outcome is whether the run did.
 *       Its base rate is the share of the fold's training runs that violated the property.</li>
 * </ul>
 * The monitor tells a forecast when it changes as shown, and the first forecast of every obligation: a new obligation
 * shows as a forecast with at least as much time left as the one before.
 *
 * @param run   the forecasts with their outcomes and base rate
 * @param scope {@link RunResult.PropertyResult#OBLIGATION} or {@link RunResult.PropertyResult#RUN}
 */
record PropertyForecasts(Reliability.Run run, String scope) {

    /** Per property id, what its forecasts said in the run whose events are {@code events}; none without forecasts. */
    static Map<String, PropertyForecasts> of(List<MonitorEvent> events, Abstraction abstraction, ForecastModel model,
                                             Map<String, Double> baseRates) {
        String safety = abstraction.safety().map(Property::id).orElse(null);
        Map<String, Collected> collected = new LinkedHashMap<>();
        Set<String> violated = new HashSet<>();
        for (MonitorEvent e : events) {
            if (e instanceof MonitorEvent.Violation v) {
                violated.add(v.property());
            } else if (e instanceof MonitorEvent.ForecastChanged c && c.property() != null
                    && !c.property().equals(safety) && !violated.contains(c.property())) {
                Collected k = collected.computeIfAbsent(c.property(), id -> new Collected());
                if (c.deadline() != null) {
                    k.deadline(c.deadline());
                } else if (c.forecast() != null) {
                    k.add(c.forecast().probability(), -1);
                }
            }
        }
        Map<String, PropertyForecasts> out = new LinkedHashMap<>();
        for (Property p : abstraction.properties()) {
            Collected k = collected.get(p.id());
            if (k == null) {
                continue;
            }
            boolean missed = violated.contains(p.id());
            if (k.deadlines) {
                List<Integer> outcomes = k.obligation.stream().map(o -> missed && o == k.obligations ? 1 : 0).toList();
                out.put(p.id(), new PropertyForecasts(new Reliability.Run(k.probabilities, outcomes,
                        obligationRate(p, model)), RunResult.PropertyResult.OBLIGATION));
            } else {
                out.put(p.id(), new PropertyForecasts(Reliability.Run.of(k.probabilities, missed,
                        baseRates.get(p.id())), RunResult.PropertyResult.RUN));
            }
        }
        return out;
    }

    /**
     * The share of the models' training obligations of {@code p} that missed the deadline, kept off 0 and 1 as the
     * forecast's own prior is ({@link Survival#missRate}), null when not known.
     */
    private static Double obligationRate(Property p, ForecastModel model) {
        if (!(p instanceof Response r) || model == null) {
            return null;
        }
        Survival s = model.obligations().get(r.id());
        return s == null || s.size() == 0 ? null : s.missRate(r.within().amount());
    }

    /** One property's forecasts in the run so far. */
    private static final class Collected {
        final List<Double> probabilities = new ArrayList<>();
        /** Each forecast's obligation: 0, 1, ... in order (-1 for a forecast of the run). */
        final List<Integer> obligation = new ArrayList<>();
        boolean deadlines;
        /** The obligation of the latest deadline forecast, -1 before one. */
        int obligations = -1;
        double left = Double.NaN;

        void deadline(Survival.Estimate e) {
            deadlines = true;
            if (obligations < 0 || e.timeLeft() >= left) {
                obligations++; // the first forecast of a new obligation: pending no time at all
            }
            left = e.timeLeft();
            if (!e.novel() && !Double.isNaN(e.probability())) {
                add(e.probability(), obligations);
            }
        }

        void add(double p, int of) {
            probabilities.add(p);
            obligation.add(of);
        }
    }
}
