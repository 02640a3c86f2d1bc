package dev.predmon.report;

import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.PropertyScore;
import dev.predmon.evaluate.Stats;

import java.util.List;
import java.util.Locale;

/**
 * The report's section on the abstraction's other properties, as the text report prints it: per property, its
 * violations, the warnings ahead of them from its own forecast (a bound's value forecast, a deadline's forecast), its
 * false alarms and lead, and beside them its baseline's: a bound's raw-value rule, a deadline's elapsed-time rule
 * ({@link PropertyScore}).
 */
final class PropertySection {

    private PropertySection() {
    }

    static void html(StringBuilder h, Evaluation e) {
        List<PropertyScore> others = PropertyScore.of(e.runs());
        if (others.isEmpty()) {
            return;
        }
        h.append("<h2 id=properties>The other properties</h2>\n");
        h.append("<table><tr><th>property</th><th>runs</th><th>no evidence</th><th>violated</th><th>warned ahead</th><th>false alarms</th>"
                + "<th>lead: median</th><th>baseline: warned ahead</th><th>false alarms</th><th>lead: median</th>"
                + "</tr>\n");
        for (PropertyScore p : others) {
            h.append(String.format(Locale.ROOT, "<tr><td>%s</td><td>%d</td><td>%d</td><td>%d</td><td>%d</td><td>%d</td>"
                            + "<td>%s</td><td>%d</td><td>%d</td><td>%s</td></tr>\n", Svg.esc(p.property()), p.runs(),
                    p.noEvidence(), p.violating(), p.warned(), p.falseAlarms(), median(p.lead()), p.baselineWarned(),
                    p.baselineAlarms(), median(p.baselineLead())));
        }
        h.append("</table>\n<p>A bound's warnings come from its own value forecast, learned from the training runs "
                + "labelled by its own violation. A deadline's come from its forecast: how long the obligation has been "
                + "pending against how long the training runs' took. The matching warns of the property a faulty "
                + "scenario's runs violate (its <code>violates</code>) when it is the only one left. A property without "
                + "a forecast (an absence, a precedence) is listed so that its violations are seen. A run in which nothing "
                + "the property speaks of occurred has no evidence for it: it is counted apart, neither safe nor "
                + "violating, and a warning in it is no false alarm. The baseline of a "
                + "deadline, chosen by the same cross-validation, warns "
                + "as soon as an obligation is pending longer than every training obligation: what the learned "
                + "durations add over \"later than ever seen\". Leads are in the runs' unit.</p>\n");
        PropertyForecastTables.html(h, others);
    }

    /** A median as the tables show it: one decimal, or "-" without any. */
    static String median(Stats s) {
        return s.n() == 0 ? "-" : String.format(Locale.ROOT, "%.1f", s.median());
    }
}
