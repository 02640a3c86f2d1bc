package dev.predmon.evaluate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * How each of the abstraction's other properties (every one but the forecast's) fared on the judged runs: its
 * violations, how many a warning came before, its false alarms (runs that kept it but were warned about it), and the
 * lead. A deadline's warnings come from its forecast (how long the obligation has been pending against the training
 * runs'); a property without a forecast (an absence, a precedence) is counted so its violations are seen.
 *
 * @param property    its id
 * @param runs        runs judged
 * @param violating   runs that violated it
 * @param warned      of those, runs warned about it before the violation
 * @param falseAlarms runs that kept it but were warned about it
 * @param lead        lead of the warned violations, in the runs' unit
 */
public record PropertyScore(String property, int runs, int violating, int warned, int falseAlarms, Stats lead) {

    /** One score per property, in the order the runs list them. */
    public static List<PropertyScore> of(List<RunResult> runs) {
        Map<String, int[]> counts = new LinkedHashMap<>();
        Map<String, List<Double>> leads = new LinkedHashMap<>();
        for (RunResult r : runs) {
            for (RunResult.PropertyResult p : r.properties()) {
                int[] c = counts.computeIfAbsent(p.property(), k -> new int[4]);
                List<Double> l = leads.computeIfAbsent(p.property(), k -> new ArrayList<>());
                c[0]++;
                if (p.violation() != null) {
                    c[1]++;
                    if (p.warning() != null && p.warning() < p.violation()) {
                        c[2]++;
                        l.add(p.violation() - p.warning());
                    }
                } else if (p.warning() != null) {
                    c[3]++;
                }
            }
        }
        List<PropertyScore> out = new ArrayList<>();
        counts.forEach((id, c) -> out.add(new PropertyScore(id, c[0], c[1], c[2], c[3], Stats.of(leads.get(id)))));
        return out;
    }
}
