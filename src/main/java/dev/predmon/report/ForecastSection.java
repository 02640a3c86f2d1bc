package dev.predmon.report;

import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.ForecastScore;

import java.util.Locale;

/**
 * The report's section on how good the forecast was, as {@link ForecastTables} prints it: the Brier score against
 * always saying the training runs' share of violations, the reliability table and the threshold sweep, drawn
 * ({@link SweepChart}) and in numbers.
 */
final class ForecastSection {

    private ForecastSection() {
    }

    static void html(StringBuilder h, Evaluation e) {
        h.append("<h2 id=forecast>Forecast</h2>\n");
        ForecastScore s = e.forecast();
        if (s == null) {
            h.append("<p>The models carry no forecast statistics, so there is no forecast to score.</p>\n");
            return;
        }
        h.append(String.format(Locale.ROOT, "<p>Over %d held-out runs: Brier score %.3f, against %.3f for always "
                        + "saying the training runs' share of violations (lower is better); %s. Warnings here follow the "
                        + "<code>%s</code> rule.</p>\n", s.runs(), s.brier(), s.baseBrier(),
                ReliabilityRows.ece(s.ece(), s.eceChance()), Svg.esc(e.rule())));
        ReliabilityRows.html(h, s.reliability());
        h.append("<p>Reliability: the forecasts binned by their probability, against how often their run "
                + "did violate. Every run weighs the same, however many forecasts it had. The ")
                .append(Svg.esc(ReliabilityRows.CHANCE)).append(" (in bold).</p>\n");
        double[] chosen = e.runs().stream().filter(r -> r.forecast() != null)
                .mapToDouble(r -> r.forecast().threshold()).filter(t -> t >= 0 && t <= 1).sorted().toArray();
        h.append("<h3 id=sweep>Threshold sweep</h3>\n<div class=sweepbox>")
                .append(SweepChart.svg(s.sweep(), chosen.length == 0 ? Double.NaN : chosen[0],
                        chosen.length == 0 ? Double.NaN : chosen[chosen.length - 1])).append('\n');
        h.append("<table><tr><th>threshold</th><th>violating runs warned</th><th>false alarms</th></tr>\n");
        for (ForecastScore.Point p : s.sweep()) {
            h.append(String.format(Locale.ROOT, "<tr><td>%.1f</td><td>%d of %d</td><td>%d of %d</td></tr>\n",
                    p.threshold(), p.warned(), p.violating(), p.falseAlarms(), p.held()));
        }
        h.append("</table></div>\n<p>Threshold sweep: a run counts as warned when its forecast reaches the threshold before "
                + "any violation. Only the probability counts here: the warning rule's other clauses (the matching, a "
                + "value below every safe run) are left out, so the runs these clauses warn are not counted.</p>\n");
    }
}
