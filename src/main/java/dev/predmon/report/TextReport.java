package dev.predmon.report;

import dev.predmon.evaluate.Confusion;
import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.PropertyScore;
import dev.predmon.evaluate.RunResult;
import dev.predmon.evaluate.ScenarioSummary;
import dev.predmon.evaluate.Stats;
import dev.predmon.evaluate.Verdict;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * The evaluation as plain-text tables for the terminal: one row per scenario, the confusion matrix, how good the
 * forecast was ({@link ForecastTables}), then one row per run with its verdict in words, times from the start of
 * the run, its forecast and its log named with its folder. Columns are as wide as their widest cell, so they stay
 * aligned whatever the file names.
 */
public final class TextReport {

    private TextReport() {
    }

    /** Prints the tables of {@code e}. */
    public static void print(PrintWriter out, Evaluation e) {
        out.println((e.mode().equals("cross-validation") ? e.folds() + "-fold cross-validation"
                : "learned on --logs, judged --test") + ", discrepancy tolerance " + e.tolerance() + ", abstraction '"
                + e.abstraction() + "'");
        out.println();
        Table scenarios = new Table("scenario", "kind", ">runs", ">warned", ">hits", ">false", ">missed", ">late",
                ">no-vio", ">no-match", ">sudden", "lead: median [min..max]", "value@warning: median [min..max]");
        for (ScenarioSummary s : e.scenarios()) {
            scenarios.row(s.scenario(), s.faulty() ? "faulty" : "nominal", s.runs(), s.warned(), s.hits(),
                    s.falseAlarms(), s.missed(), s.late(), s.noViolation(), s.noMatch(), s.sudden(),
                    s.lead().n() == 0 ? "-" : stats(s.lead()) + " " + s.leadUnit(), stats(s.valueAtWarning()));
        }
        scenarios.print(out);
        out.println();
        out.println("sudden: " + sudden(e.runs()));
        Confusion c = e.confusion();
        out.println();
        out.printf(Locale.ROOT, "confusion (actual x predicted): faulty&warned-in-time %d, faulty&missed %d, "
                        + "nominal&warned %d, nominal&quiet %d; faulty without violation (unscored) %d%n",
                c.truePositives(), c.falseNegatives(), c.falsePositives(), c.trueNegatives(), c.unscored());
        out.printf(Locale.ROOT, "recall %s, false-alarm rate %s (warning rule: %s)%n", percent(c.recall()),
                percent(c.falseAlarmRate()), e.rule());
        ForecastTables.print(out, e);
        List<PropertyScore> others = PropertyScore.of(e.runs());
        if (!others.isEmpty()) {
            out.println();
            out.println("the other properties (warnings from their own forecasts: a bound's value forecast, a deadline's "
                    + "forecast, an absence's or a precedence's event forecast; or the matching of a faulty scenario that violates them; lead in the runs' unit)");
            Table t = new Table("property", ">runs", ">no evidence", ">violated", ">warned ahead", ">false alarms", "lead: median",
                    ">baseline: warned ahead", ">false alarms", "lead: median");
            for (PropertyScore p : others) {
                t.row(p.property(), p.runs(), p.noEvidence(), p.violating(), p.warned(), p.falseAlarms(), PropertySection.median(p.lead()),
                        p.baselineWarned(), p.baselineAlarms(), PropertySection.median(p.baselineLead()));
            }
            t.print(out);
            out.println("baseline, on the same runs: a bound's raw-value rule (warn below the lowest value a safe "
                    + "training run of the fold read, above the highest for a ceiling); a deadline's elapsed-time rule "
                    + "(warn once an obligation is pending longer than every training obligation of the fold); an absence's or a precedence's "
                    + "base rate (warn every run where the fold's training runs violated it at even odds or more, "
                    + "else none)");
            PropertyForecastTables.print(out, others);
        }
        out.println();
        out.println("times from the start of each run");
        Table runs = new Table("log", ">run", ">fold", "scenario", "verdict", ">warning", ">violation", ">lead",
                ">forecast", "eliminated (model@line)", "note");
        int n = 0;
        for (RunResult r : e.runs()) {
            RunView v = RunView.of(++n, r);
            runs.row(v.log(), v.runText(), r.fold() < 0 ? "-" : Integer.toString(r.fold()), r.scenario(), v.verdict(),
                    v.at(r.warningTime()), v.at(r.violationTime()), v.duration(r.lead()), v.forecastText(),
                    r.eliminations().stream().map(x -> x.model() + "@" + x.line()).collect(Collectors.joining(" ")),
                    v.note());
        }
        runs.print(out);
    }

    /**
     * What "sudden" means, with its counts on these runs: a sentence that holds for any data, since a sudden
     * violation that the models still warned ahead of is counted as warned, not as unforeseeable.
     */
    public static String sudden(List<RunResult> runs) {
        long sudden = runs.stream().filter(RunResult::sudden).count();
        long warned = runs.stream().filter(r -> r.sudden() && r.verdict() == Verdict.WARNED_BEFORE_VIOLATION).count();
        return String.format(Locale.ROOT, "a violation with fewer than %d readings within %.0f points above the bound "
                        + "on the way to it (the value fell past that band in a few readings, so a monitor of the value alone "
                        + "has little time); %d of the %d sudden violations here were still warned ahead, from the "
                        + "behaviour", RunResult.SUDDEN_READINGS, RunResult.APPROACH_BAND, warned, sudden);
    }

    static String stats(Stats s) {
        return s.n() == 0 ? "-" : String.format(Locale.ROOT, "%.1f [%.1f..%.1f]", s.median(), s.min(), s.max());
    }

    static String percent(Double d) {
        return d == null ? "-" : String.format(Locale.ROOT, "%.1f%%", d * 100);
    }

    /** Columns as wide as their widest cell; a header starting with {@code >} is right-aligned (numbers). */
    private static final class Table {
        private final List<String> headers = new ArrayList<>();
        private final boolean[] right;
        private final List<String[]> rows = new ArrayList<>();

        Table(String... headers) {
            right = new boolean[headers.length];
            for (int i = 0; i < headers.length; i++) {
                right[i] = headers[i].startsWith(">");
                this.headers.add(right[i] ? headers[i].substring(1) : headers[i]);
            }
        }

        void row(Object... cells) {
            String[] r = new String[cells.length];
            for (int i = 0; i < cells.length; i++) {
                r[i] = String.valueOf(cells[i]);
            }
            rows.add(r);
        }

        void print(PrintWriter out) {
            int[] width = new int[headers.size()];
            for (int i = 0; i < width.length; i++) {
                width[i] = headers.get(i).length();
                for (String[] r : rows) {
                    width[i] = Math.max(width[i], r[i].length());
                }
            }
            line(out, headers.toArray(String[]::new), width);
            for (String[] r : rows) {
                line(out, r, width);
            }
        }

        private void line(PrintWriter out, String[] cells, int[] width) {
            StringBuilder b = new StringBuilder();
            for (int i = 0; i < cells.length; i++) {
                String cell = cells[i];
                String pad = " ".repeat(width[i] - cell.length());
                b.append(i == 0 ? "" : "  ").append(right[i] ? pad + cell : i == cells.length - 1 ? cell : cell + pad);
            }
            out.println(b.toString().stripTrailing());
        }
    }
}
