package dev.predmon.cli;

import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.ForecastScore;

import java.io.PrintWriter;
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
                        + " training base rate: %.3f; lower is better), expected calibration error %.3f%n", s.runs(),
                e.rule(), s.brier(), s.baseBrier(), s.ece());
        out.println("reliability: predicted probability against observed frequency of violation (runs weigh the same)");
        out.printf(Locale.ROOT, "  %-11s %9s %8s %10s %9s%n", "P in", "forecasts", "runs", "predicted", "observed");
        for (ForecastScore.Bin b : s.reliability()) {
            out.printf(Locale.ROOT, "  %.1f - %.1f  %9d %8.1f %10.2f %9.2f%n", b.from(), b.to(), b.forecasts(),
                    b.weight(), b.predicted(), b.observed());
        }
        out.println("threshold sweep: a run is warned when its forecast reaches the threshold before any violation");
        out.printf(Locale.ROOT, "  %-9s %-22s %s%n", "threshold", "violating runs warned", "false alarms");
        for (ForecastScore.Point p : s.sweep()) {
            out.printf(Locale.ROOT, "  %-9.1f %-22s %d of %d%n", p.threshold(), p.warned() + " of " + p.violating(),
                    p.falseAlarms(), p.held());
        }
    }
}
