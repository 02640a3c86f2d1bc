package dev.predmon.report;

import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.ForecastScore;
import dev.predmon.evaluate.Reliability;

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
                        + "saying the training runs' share of violations (lower is better); expected calibration error "
                        + "%.3f. Warnings here follow the <code>%s</code> rule.</p>\n", s.runs(), s.brier(), s.baseBrier(),
                s.ece(), Svg.esc(e.rule())));
        h.append("<table><tr><th>P in</th><th>forecasts</th><th>runs' worth</th><th>predicted</th><th>observed</th>"
                + "</tr>\n");
        for (Reliability.Bin b : s.reliability()) {
            h.append(String.format(Locale.ROOT, "<tr><td>%.1f - %.1f</td><td>%d</td><td>%.1f</td><td>%.2f</td>"
                    + "<td>%.2f</td></tr>\n", b.from(), b.to(), b.forecasts(), b.weight(), b.predicted(), b.observed()));
        }
        h.append("</table>\n<p>Reliability: the forecasts binned by their probability, against how often their run "
                + "did violate. Every run weighs the same, however many forecasts it had.</p>\n");
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
