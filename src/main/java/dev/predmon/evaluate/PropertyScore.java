package dev.predmon.evaluate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * How each of the abstraction's other properties (every one but the forecast's) fared on the judged runs: its
 * violations, how many a warning came before, its false alarms (runs that kept it but were warned about it), and the
 * lead. A bound's warnings come from its own value forecast (learned from the training runs labelled by its own
 * violation), a deadline's from its forecast (how long the obligation has been pending against the training runs'),
 * and a property a faulty scenario's runs violate ({@code violates} in its {@code scenario.json}) is also warned of by
 * the matching; a property without either (an absence, a precedence) is counted so its violations are seen. How good
 * each property's forecast was is {@link Reliability}'s score of its forecasts ({@link PropertyForecasts}).
 *
 * <p>Beside them, the property's baseline on the same runs, chosen by the same cross-validation: a deadline's
 * elapsed-time rule (warn as soon as an obligation has been pending longer than every training obligation of the
 * fold's models: what the learned durations add over "later than ever seen"), a bound's raw-value rule (warn below
 * the lowest value a safe training run of the fold read, above the highest for a ceiling).
 *
 * @param property        its id
 * @param runs            runs judged: those with evidence for it (a run in which nothing it speaks of occurred is
 *                        neither safe nor violating for it, so its warnings are no false alarms either)
 * @param violating       runs that violated it
 * @param warned          of those, runs warned about it before the violation
 * @param falseAlarms     runs that kept it but were warned about it
 * @param lead            lead of the warned violations, in the runs' unit
 * @param baselineWarned  violating runs the baseline warned before the violation
 * @param baselineAlarms  runs that kept it but the baseline warned
 * @param baselineLead    the baseline's lead
 * @param forecast        how good its forecast was ({@link Reliability}: Brier score against the base rate,
 *                        calibration error, reliability table), or null when it has no forecast with a probability
 *                        on these runs
 * @param scope           what its forecasts are about ({@link RunResult.PropertyResult#scope}), null without one
 * @param noEvidence      runs with no evidence for it ({@link RunResult.PropertyResult#noEvidence}), not judged
 * @param noForecast      why the models gave it no forecast ({@link RunResult.PropertyResult#noForecast}), each
 *                        reason once, or null
 */
public record PropertyScore(String property, int runs, int violating, int warned, int falseAlarms, Stats lead,
                            int baselineWarned, int baselineAlarms, Stats baselineLead, Reliability forecast,
                            String scope, int noEvidence, String noForecast) {

    /** A score not told why a property has no forecast. */
    public PropertyScore(String property, int runs, int violating, int warned, int falseAlarms, Stats lead,
                         int baselineWarned, int baselineAlarms, Stats baselineLead, Reliability forecast,
                         String scope, int noEvidence) {
        this(property, runs, violating, warned, falseAlarms, lead, baselineWarned, baselineAlarms, baselineLead,
                forecast, scope, noEvidence, null);
    }

    /** A score on runs that all had evidence for the property. */
    public PropertyScore(String property, int runs, int violating, int warned, int falseAlarms, Stats lead,
                         int baselineWarned, int baselineAlarms, Stats baselineLead, Reliability forecast,
                         String scope) {
        this(property, runs, violating, warned, falseAlarms, lead, baselineWarned, baselineAlarms, baselineLead,
                forecast, scope, 0);
    }

    /** A score without a forecast. */
    public PropertyScore(String property, int runs, int violating, int warned, int falseAlarms, Stats lead,
                         int baselineWarned, int baselineAlarms, Stats baselineLead) {
        this(property, runs, violating, warned, falseAlarms, lead, baselineWarned, baselineAlarms, baselineLead, null,
                null);
    }

    /** One score per property, in the order the runs list them. */
    public static List<PropertyScore> of(List<RunResult> runs) {
        Map<String, int[]> counts = new LinkedHashMap<>();
        Map<String, List<Double>> leads = new LinkedHashMap<>();
        Map<String, List<Double>> baselineLeads = new LinkedHashMap<>();
        Map<String, List<Reliability.Run>> forecasts = new LinkedHashMap<>();
        Map<String, String> scopes = new LinkedHashMap<>();
        Map<String, Set<String>> why = new LinkedHashMap<>();
        for (RunResult r : runs) {
            for (RunResult.PropertyResult p : r.properties()) {
                if (p.noForecast() != null) {
                    why.computeIfAbsent(p.property(), k -> new LinkedHashSet<>()).add(p.noForecast());
                }
                if (p.forecasts() != null) {
                    forecasts.computeIfAbsent(p.property(), k -> new ArrayList<>()).add(p.forecasts());
                    scopes.putIfAbsent(p.property(), p.scope());
                }
                int[] c = counts.computeIfAbsent(p.property(), k -> new int[7]);
                List<Double> l = leads.computeIfAbsent(p.property(), k -> new ArrayList<>());
                List<Double> b = baselineLeads.computeIfAbsent(p.property(), k -> new ArrayList<>());
                if (p.noEvidence()) {
                    c[6]++;
                    continue;
                }
                c[0]++;
                if (p.violation() != null) {
                    c[1]++;
                    if (p.warning() != null && p.warning() < p.violation()) {
                        c[2]++;
                        l.add(p.violation() - p.warning());
                    }
                    if (p.beyond() != null && p.beyond() < p.violation()) {
                        c[4]++;
                        b.add(p.violation() - p.beyond());
                    }
                } else {
                    c[3] += p.warning() != null ? 1 : 0;
                    c[5] += p.beyond() != null ? 1 : 0;
                }
            }
        }
        List<PropertyScore> out = new ArrayList<>();
        counts.forEach((id, c) -> {
            Reliability f = Reliability.of(forecasts.getOrDefault(id, List.of()));
            out.add(new PropertyScore(id, c[0], c[1], c[2], c[3], Stats.of(leads.get(id)), c[4], c[5],
                    Stats.of(baselineLeads.get(id)), f, f == null ? null : scopes.get(id), c[6],
                    why.containsKey(id) ? String.join("; ", why.get(id)) : null));
        });
        return out;
    }
}
