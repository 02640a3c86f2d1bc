package dev.predmon.report;

import dev.predmon.evaluate.RunResult;
import dev.predmon.evaluate.Verdict;
import dev.predmon.parse.Clock;

import java.nio.file.Path;
import java.util.Locale;

/**
 * One judged run as the report shows it, in the text tables and the HTML page alike: its log named with its
 * folder, its run number, its verdict in a reader's words, and every time counted from the start of the run.
 *
 * @param number   1, 2, ... in the evaluation's order; the HTML anchors of its table row and plot use it
 * @param result   the run as {@code evaluate} judged it
 * @param log      the log's folder and file name, e.g. {@code depleted/depleted-1.log}
 * @param run      the run's number within its log (0, 1, ...), or null for a log that holds one run
 * @param verdict  what happened, in words: {@code warned ahead}, {@code violated without warning}, ...
 * @param tone     how the verdict reads: {@code good}, {@code bad}, {@code unknown} or {@code plain}
 * @param forecast the run's forecast, or null where the run result carries none
 */
public record RunView(int number, RunResult result, String log, Integer run, String verdict, String tone,
                      Forecast forecast) {

    /** What is shown where a value is absent. */
    public static final String NONE = "—";

    /**
     * What the forecast said of the run: at its warning where it has one, else its highest probability.
     *
     * @param probability     P(the run violates the property), 0 to 1
     * @param timeToViolation the estimated time to the violation, in the run's unit, or null
     * @param atWarning       whether this is the forecast at the warning (else the run's highest probability)
     */
    public record Forecast(double probability, Double timeToViolation, boolean atWarning) {
    }

    /** The view of {@code r}, the {@code number}-th run of the evaluation. */
    public static RunView of(int number, RunResult r) {
        return new RunView(number, r, withFolder(r.log().log()), r.log().numberIfSeveral(), verdict(r), tone(r),
                forecastOf(r));
    }

    /** The file name with its folder ({@code depleted/depleted-1.log}): the folder is often the scenario. */
    static String withFolder(Path log) {
        Path file = log.getFileName();
        Path folder = log.getParent() == null ? null : log.getParent().getFileName();
        return file == null ? log.toString() : folder == null ? file.toString() : folder + "/" + file;
    }

    /**
     * The run's forecast for the forecast column: the one at the warning, which is what an operator acts on, or for
     * a run without a warning the highest probability it reached before any violation (what the threshold sweep
     * compares); null where the models carry no forecast.
     */
    static Forecast forecastOf(RunResult r) {
        RunResult.ForecastTrace f = r.forecast();
        if (f == null || (f.atWarning() == null && f.probabilities().isEmpty())) {
            return null;
        }
        return f.atWarning() != null ? new Forecast(f.atWarning().probability(), f.atWarning().timeToViolation(), true)
                : new Forecast(f.peak(), null, false);
    }

    /**
     * The verdict in words. A run during which no model matched and that was not warned is "no model matches",
     * never "held": the monitor was blind from that point on, which says nothing good about the run.
     */
    static String verdict(RunResult r) {
        return switch (r.verdict()) {
            case WARNED_BEFORE_VIOLATION -> "warned ahead";
            case WARNED_LATE -> "warned too late";
            case MISSED -> "violated without warning";
            case FALSE_ALARM -> "false alarm";
            case WARNED_NO_VIOLATION -> "warned, held";
            case QUIET, QUIET_NO_VIOLATION -> r.noMatch() ? "no model matches" : "held";
        };
    }

    private static String tone(RunResult r) {
        Verdict v = r.verdict();
        if (v == Verdict.WARNED_BEFORE_VIOLATION) {
            return "good";
        }
        if (v == Verdict.MISSED || v == Verdict.WARNED_LATE || v == Verdict.FALSE_ALARM) {
            return "bad";
        }
        if (r.noMatch() && !v.warned()) {
            return "unknown";
        }
        return v == Verdict.QUIET ? "good" : "plain";
    }

    /** The {@code id} of the run's plot in the HTML page. */
    public String anchor() {
        return "run-" + number;
    }

    /** The {@code id} of the run's row in the HTML page's table. */
    public String rowAnchor() {
        return "row-" + number;
    }

    /** The run's clock. */
    public Clock clock() {
        return result.unit().equals(Clock.TICKS.unit()) ? Clock.TICKS : Clock.SECONDS;
    }

    /** A log time (the warning's, an elimination's) counted from the start of the run, or {@link #NONE}. */
    public String at(Double logTime) {
        return logTime == null ? NONE : amount(clock(), logTime - result.start());
    }

    /** A duration in the run's clock, or {@link #NONE}: {@code 3.9 s}, {@code 12 ticks}. */
    public String duration(Double d) {
        return d == null ? NONE : amount(clock(), d);
    }

    /** A duration in {@code clock}'s unit: {@code 3.9 s}, {@code 12 ticks}. */
    public static String amount(Clock clock, double d) {
        return clock == Clock.TICKS ? String.format(Locale.ROOT, "%.0f ticks", d)
                : String.format(Locale.ROOT, "%.1f s", d);
    }

    /**
     * The forecast, short enough for a table cell, or {@link #NONE}: {@code 97%, in 3.5 s} at the warning (its
     * probability and time to the violation), {@code max 40%} for a run without a warning.
     */
    public String forecastText() {
        if (forecast == null) {
            return NONE;
        }
        String p = String.format(Locale.ROOT, "%.0f%%", forecast.probability() * 100);
        return forecast.atWarning() ? p + (forecast.timeToViolation() == null ? "" : ", in "
                + duration(forecast.timeToViolation())) : "max " + p;
    }

    /** The run's number within its log, or {@link #NONE}. */
    public String runText() {
        return run == null ? NONE : run.toString();
    }

    /**
     * What a reader should know beside the verdict, or an empty string: that no model matched from some point on
     * (the monitor was blind from there), that the violation was sudden, and how late a late warning was.
     */
    public String note() {
        StringBuilder n = new StringBuilder();
        if (result.noMatch() && !verdict.equals("no model matches")) {
            n.append("no model matched from ").append(at(result.noMatchTime()));
        } else if (result.noMatch()) {
            n.append("from ").append(at(result.noMatchTime())).append(" on");
        }
        if (result.sudden()) {
            n.append(n.isEmpty() ? "" : "; ").append("sudden: ").append(result.nearBound())
                    .append(result.nearBound() == 1 ? " reading" : " readings").append(" near the bound");
            if (result.beforeViolation() != null) {
                n.append(String.format(Locale.ROOT, ", fell from %.1f", result.beforeViolation()));
            }
        }
        if (result.verdict() == Verdict.WARNED_LATE) {
            double late = result.warningTime() - result.violationTime();
            n.append(n.isEmpty() ? "" : "; ").append(late == 0 ? "warned at the violation"
                    : "warned " + duration(late) + " after it");
        }
        return n.toString();
    }
}
