package dev.predmon.report;

import dev.predmon.evaluate.Reliability;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;

/**
 * A reliability table, in text and in HTML, for the forecast's property and every other one alike: each bin's
 * forecasts, runs' worth, predicted and observed frequency, and where chance alone puts a calibrated forecast's
 * observed frequency on the same runs (an observed frequency outside it is marked: more than chance).
 */
final class ReliabilityRows {

    /** What the chance column means, in one sentence. */
    static final String CHANCE = "chance: where a calibrated forecast's observed frequency falls 9 times in 10 on"
            + " these same runs; outside it, the gap is more than chance";

    private ReliabilityRows() {
    }

    /** "expected calibration error 0.089 (a calibrated forecast shows up to 0.137 on these runs by chance, ...)". */
    static String ece(double ece, double chance) {
        return String.format(Locale.ROOT, "expected calibration error %.3f (a calibrated forecast shows up to %.3f on"
                + " these runs by chance, 9 times in 10)", ece, chance);
    }

    static void text(PrintWriter out, String indent, List<Reliability.Bin> bins) {
        out.printf(Locale.ROOT, "%s%-11s %9s %8s %10s %9s  %s%n", indent, "P in", "forecasts", "runs", "predicted",
                "observed", "chance");
        for (Reliability.Bin b : bins) {
            out.printf(Locale.ROOT, "%s%.1f - %.1f  %9d %8.1f %10.2f %9.2f  %.2f-%.2f%s%n", indent, b.from(), b.to(),
                    b.forecasts(), b.weight(), b.predicted(), b.observed(), b.chanceLow(), b.chanceHigh(),
                    b.withinChance() ? "" : "  more than chance");
        }
    }

    static void html(StringBuilder h, List<Reliability.Bin> bins) {
        h.append("<table><tr><th>P in</th><th>forecasts</th><th>runs' worth</th><th>predicted</th><th>observed</th>"
                + "<th>chance</th></tr>\n");
        for (Reliability.Bin b : bins) {
            boolean within = b.withinChance();
            h.append(String.format(Locale.ROOT, "<tr><td>%.1f - %.1f</td><td>%d</td><td>%.1f</td><td>%.2f</td>"
                            + "<td>%s%.2f%s</td><td>%.2f - %.2f</td></tr>\n", b.from(), b.to(), b.forecasts(),
                    b.weight(), b.predicted(), within ? "" : "<b>", b.observed(), within ? "" : "</b>", b.chanceLow(),
                    b.chanceHigh()));
        }
        h.append("</table>\n");
    }
}
