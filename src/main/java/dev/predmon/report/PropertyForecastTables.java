package dev.predmon.report;

import dev.predmon.evaluate.PropertyScore;
import dev.predmon.evaluate.Reliability;
import dev.predmon.evaluate.RunResult;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;

/**
 * How good each other property's forecast was, in words the text report and the HTML report share: its Brier score
 * against the base rate, its expected calibration error and the rows of its reliability table that have forecasts
 * ({@link PropertyScore#forecast()}).
 */
final class PropertyForecastTables {

    /** What the scores mean, said once above them. */
    static final String HEADER = "forecasts of the other properties, each forecast before the property's violation "
            + "(or the run's end) scored against its outcome; runs weigh the same. A deadline forecast is P(the "
            + "pending obligation misses its deadline): its outcome is whether that obligation missed it (one "
            + "discharged in time, or pending at the run's end, did not), its base rate the share of the fold's "
            + "training obligations that missed; forecasts past every training obligation have no probability and are "
            + "not scored. A value forecast (a bound's) and an event forecast (an absence's, a precedence's) are P(the run "
            + "violates the property), their base rate the share of the fold's training runs that violated it. Lower Brier is better; " + ReliabilityRows.CHANCE + ".";

    private PropertyForecastTables() {
    }

    static void print(PrintWriter out, List<PropertyScore> scores) {
        out.println();
        out.println(HEADER);
        for (PropertyScore p : scores) {
            Reliability r = p.forecast();
            out.println("  " + p.property() + ": " + summary(p));
            if (r == null) {
                continue;
            }
            ReliabilityRows.text(out, "    ", r.bins());
        }
    }

    static void html(StringBuilder h, List<PropertyScore> scores) {
        if (scores.stream().allMatch(p -> p.forecast() == null)) {
            h.append("<p>No other property has a forecast with a probability on these runs.</p>\n");
            return;
        }
        h.append("<h3 id=property-forecasts>Their forecasts</h3>\n<p>").append(Svg.esc(Character.toUpperCase(HEADER.charAt(0)) + HEADER.substring(1))).append("</p>\n");
        for (PropertyScore p : scores) {
            Reliability r = p.forecast();
            h.append("<p><b>").append(Svg.esc(p.property())).append("</b>: ").append(Svg.esc(summary(p)))
                    .append("</p>\n");
            if (r == null) {
                continue;
            }
            ReliabilityRows.html(h, r.bins());
        }
    }

    /** As {@link #summary(Reliability, String)}, saying why a property without a forecast has none where known. */
    static String summary(PropertyScore p) {
        return p.forecast() == null && p.noForecast() != null ? "no forecast: " + p.noForecast()
                : summary(p.forecast(), p.scope());
    }

    /**
     * One property's forecast in a line: "per obligation, 30 runs, 412 forecasts, 30 with a miss: Brier score 0.081
     * (always saying the base rate: 0.210), expected calibration error 0.050"; "no forecast" without one.
     */
    static String summary(Reliability r, String scope) {
        if (r == null) {
            return "no forecast";
        }
        String outcome = RunResult.PropertyResult.OBLIGATION.equals(scope) ? "with an obligation that missed"
                : "violated";
        String base = r.baseBrier() == null ? "base rate not known"
                : String.format(Locale.ROOT, "always saying the base rate: %.3f", r.baseBrier());
        String line = String.format(Locale.ROOT, "per %s, %d runs with forecasts, %d forecasts, %d %s: Brier score "
                        + "%.3f (%s), %s", scope, r.runs(), r.forecasts(), r.violating(),
                outcome, r.brier(), base, ReliabilityRows.ece(r.ece(), r.eceChance()));
        if (r.violating() == 0) {
            line += "; nothing was violated on these runs, so the Brier score cannot show skill (every run held)";
        }
        return line;
    }
}
