package dev.predmon.report;

import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.ForecastScore;
import dev.predmon.evaluate.ValueRule;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;

/** Prints how good the forecast was: the Brier score against the base rate, the reliability table, the sweep. */
final class ForecastTables {

    private ForecastTables() {
    }

    static void print(PrintWriter out, Evaluation e) {
        ForecastScore s = e.forecast();
        out.println();
        if (s == null) {
            out.println("forecast: none (the models carry no forecast statistics)");
            return;
        }
        out.printf(Locale.ROOT, "forecast over %d held-out runs (warning rule: %s): Brier score %.3f (always saying the"
                        + " training base rate: %.3f; lower is better), %s%n", s.runs(),
                e.rule(), s.brier(), s.baseBrier(), ReliabilityRows.ece(s.ece(), s.eceChance()));
        out.println("reliability: predicted probability against observed frequency of violation (runs weigh the same);"
                + " " + ReliabilityRows.CHANCE);
        ReliabilityRows.text(out, "  ", s.reliability());
        out.println("baseline, chosen by the same cross-validation: what the learned machines add");
        for (ValueRule r : List.of(s.judged(), s.rawValue())) {
            out.printf(Locale.ROOT, "  %-66s %s%n", r.rule(), words(r));
        }
        out.println("threshold sweep: a run is warned when its forecast reaches the threshold before any violation");
        out.printf(Locale.ROOT, "  %-9s %-22s %s%n", "threshold", "violating runs warned", "false alarms");
        for (ForecastScore.Point p : s.sweep()) {
            out.printf(Locale.ROOT, "  %-9.1f %-22s %d of %d%n", p.threshold(), p.warned() + " of " + p.violating(),
                    p.falseAlarms(), p.held());
        }
    }

    /** A rule's counts in one line: "2 of 11 violations warned ahead, 1 of 32 false alarms, lead median 56.5". */
    static String words(ValueRule r) {
        return String.format(Locale.ROOT, "%d of %d violations warned ahead, %d of %d false alarms, lead median %s",
                r.warned(), r.violating(), r.falseAlarms(), r.held(),
                r.lead().n() == 0 ? "-" : String.format(Locale.ROOT, "%.1f", r.lead().median()));
    }
}
