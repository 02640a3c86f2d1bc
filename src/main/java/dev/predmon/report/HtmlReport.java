package dev.predmon.report;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.evaluate.Confusion;
import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.RunResult;
import dev.predmon.evaluate.ScenarioSummary;
import dev.predmon.files.AtomicFiles;
import dev.predmon.parse.Clock;
import dev.predmon.property.Bound;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * The evaluation as one self-contained HTML file: no script and no external reference, so it opens anywhere
 * without network. Sections: the summary per scenario, the confusion matrix, how good the forecast was
 * ({@link ForecastSection}), the table of runs
 * ({@link RunTable}, each row linked to its run's plot), the distribution of leads ({@link LeadHistogram}), one
 * plot per run ({@link RunPlot}) and the learned models drawn ({@link ModelSection}).
 *
 * <p>Everything the drawings share is on the page once: the style sheet ({@code report.css}) and the SVG
 * definitions ({@link MachineDrawing#DEFS}). A drawing names classes and refers to the definitions, so that a
 * report of a hundred runs stays well under a megabyte.
 */
public final class HtmlReport {

    /** Runs plotted at most; every run has a row in the table all the same. */
    public static final int MAX_PLOTS = 300;
    /** Points read per run at most, before the plot thins them to what it can show. */
    private static final int MAX_POINTS = 20_000;
    private static final String CSS = css();
    /**
     * How every report begins: {@code evaluate --report} replaces an existing file only when it begins so (one it
     * wrote), never a log, an index or a page of the user's.
     */
    public static final String SIGNATURE = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            + "<title>predmon evaluation</title>";

    private HtmlReport() {
    }

    /** Writes the report of {@code e} to {@code file}, completely or not at all ({@link AtomicFiles}). */
    public static void write(Evaluation e, Abstraction abstraction, Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        AtomicFiles.replace(file, html(e, abstraction));
    }

    /** The report's text. */
    public static String html(Evaluation e, Abstraction abstraction) throws IOException {
        List<RunView> runs = new ArrayList<>();
        for (RunResult r : firstWhatWentWrong(e.runs())) {
            runs.add(RunView.of(runs.size() + 1, r));
        }
        Bound rule = abstraction.safety().orElse(null);
        int plotted = rule == null ? 0 : Math.min(MAX_PLOTS, runs.size());
        StringBuilder h = new StringBuilder(1 << 18);
        h.append(SIGNATURE).append('\n')
                .append("<style>\n").append(CSS).append("</style></head><body>\n")
                .append("<svg class=defs aria-hidden=true><defs>").append(MachineDrawing.DEFS).append("</defs></svg>\n");
        h.append("<h1>predmon evaluation</h1>\n<p>")
                .append(e.mode().equals("cross-validation")
                        ? e.folds() + "-fold cross-validation over the training logs (every run is judged by models "
                        + "learned without it)"
                        : "models learned on the training logs, every run of the test logs judged")
                .append("; discrepancy tolerance ").append(e.tolerance()).append("; warning rule <code>")
                .append(Svg.esc(e.rule()))
                .append("</code>; abstraction <code>")
                .append(Svg.esc(e.abstraction())).append("</code>. Each run was replayed through the code path of "
                        + "<code>watch --no-follow</code>, built-in safety monitor included.</p>\n")
                .append("<nav><a href=#summary>Summary</a><a href=#confusion>Confusion matrix</a>"
                        + "<a href=#forecast>Forecast</a><a href=#runs>Runs</a><a href=#leads>Leads</a><a href=#plots>Plots</a>"
                        + "<a href=#models>Learned models</a></nav>\n");
        summary(h, e);
        confusion(h, e.confusion());
        ForecastSection.html(h, e);
        PropertySection.html(h, e);
        for (String n : e.notes()) {
            h.append("<p>Note: ").append(Svg.esc(n)).append("</p>\n");
        }
        h.append("<h2 id=runs>Runs</h2>\n<p>Violations missed first, then false alarms, then runs no model "
                + "matched, then the rest.</p>\n");
        RunTable.html(h, runs, plotted);
        leads(h, e);
        plots(h, runs, plotted, abstraction, rule);
        ModelSection.html(h, e);
        h.append("</body></html>\n");
        return h.toString();
    }

    /**
     * The runs in the order a reader looks for them: the violations missed (late warnings included), then the false
     * alarms, then the runs no model matched, then the rest; each group in the evaluation's order.
     */
    static List<RunResult> firstWhatWentWrong(List<RunResult> runs) {
        List<RunResult> sorted = new ArrayList<>(runs);
        sorted.sort(Comparator.comparingInt(HtmlReport::rank)); // stable: each group keeps its order
        return sorted;
    }

    private static int rank(RunResult r) {
        return switch (r.verdict()) {
            case MISSED, WARNED_LATE -> 0;
            case FALSE_ALARM -> 1;
            default -> r.noMatch() && !r.verdict().warned() ? 2 : 3;
        };
    }

    private static void summary(StringBuilder h, Evaluation e) {
        h.append("<h2 id=summary>Summary</h2>\n<table><tr><th class=l>scenario</th><th class=l>kind</th><th>runs</th>"
                + "<th>warned</th><th>hits</th><th>false alarms</th><th>missed</th><th>of which late</th>"
                + "<th>no violation</th><th>no match</th><th>sudden violations</th><th>lead: median [min..max]</th>"
                + "<th>value at warning: median [min..max]</th></tr>\n");
        for (ScenarioSummary s : e.scenarios()) {
            h.append("<tr><td class=l>").append(Svg.esc(s.scenario())).append("</td><td class=l>")
                    .append(s.faulty() ? "faulty" : "nominal").append("</td>");
            for (int v : new int[] {s.runs(), s.warned(), s.hits(), s.falseAlarms(), s.missed(), s.late(),
                    s.noViolation(), s.noMatch(), s.sudden()}) {
                h.append("<td>").append(v).append("</td>");
            }
            h.append("<td>").append(s.lead().n() == 0 ? "-" : TextReport.stats(s.lead()) + " " + s.leadUnit())
                    .append("</td><td>").append(TextReport.stats(s.valueAtWarning())).append("</td></tr>\n");
        }
        h.append("</table>\n<p>Missed: a faulty run without a warning strictly before its violation (late warnings "
                + "included). No violation: a faulty run whose log ends before the property is violated. No match: "
                + "runs during which, at some point, no learned model matched: from there on the monitor had no model "
                + "to predict with. Sudden: ").append(Svg.esc(TextReport.sudden(e.runs()))).append(".</p>\n");
    }

    private static void confusion(StringBuilder h, Confusion c) {
        h.append("<h2 id=confusion>Confusion matrix</h2>\n<table><tr><th class=l>actual \\ predicted</th>"
                        + "<th>warned before violation</th><th>not warned (in time)</th></tr>\n")
                .append("<tr><th class=l>faulty</th><td class=good>").append(c.truePositives())
                .append("</td><td class=bad>").append(c.falseNegatives()).append("</td></tr>\n")
                .append("<tr><th class=l>nominal</th><td class=bad>").append(c.falsePositives())
                .append("</td><td class=good>").append(c.trueNegatives()).append("</td></tr>\n</table>\n")
                .append("<p>Recall ").append(TextReport.percent(c.recall())).append(", false-alarm rate ")
                .append(TextReport.percent(c.falseAlarmRate())).append("; faulty runs without violation, not scored: ")
                .append(c.unscored()).append(".</p>\n");
    }

    private static void leads(StringBuilder h, Evaluation e) {
        h.append("<h2 id=leads>Distribution of leads</h2>\n");
        double[] leads = e.runs().stream().filter(r -> r.lead() != null).mapToDouble(RunResult::lead).toArray();
        if (leads.length == 0) {
            h.append("<p>No faulty run was warned before its violation, so there is no lead to show.</p>\n");
            return;
        }
        // Leads of logs with time stamps are seconds, of console captures ticks: the histogram takes the hits' unit.
        Clock clock = e.runs().stream().filter(r -> r.lead() != null).allMatch(r -> r.unit().equals(Clock.TICKS.unit()))
                ? Clock.TICKS : Clock.SECONDS;
        h.append("<p>The lead of the warning over the violation, over the ").append(leads.length)
                .append(leads.length == 1 ? " run" : " runs").append(" warned ahead.</p>\n")
                .append(LeadHistogram.svg(leads, clock)).append('\n');
    }

    private static void plots(StringBuilder h, List<RunView> runs, int plotted, Abstraction abstraction,
                              Bound rule) throws IOException {
        h.append("<h2 id=plots>Plots of the runs</h2>\n");
        if (rule == null) {
            h.append("<p>The abstraction has no safety property, so there is no level to plot.</p>\n");
            return;
        }
        if (runs.size() > plotted) {
            h.append("<p>Only the first ").append(plotted).append(" of ").append(runs.size())
                    .append(" runs are plotted; every run is in the table above and in the JSON output.</p>\n");
        }
        h.append("<p>").append(Svg.esc(rule.name())).append(": the watched value over time from the start of the run; "
                + "orange dashed line: the warning; red line: the violation; shaded between them: the lead; brown "
                + "dotted line: from there no model matched; grey dashed: the bound ").append(fmt(rule.floor()))
                .append("; purple, on the scale at the right: the forecast's probability of a violation as the run "
                        + "went, and dotted across, the threshold at which it warns. The number before each plot leads "
                        + "back to its row in the table.</p>\n<div class=plots>\n");
        for (RunView v : runs.subList(0, plotted)) {
            Timeline t = Timeline.ofRun(v.result().log(), abstraction, rule, MAX_POINTS);
            RunResult r = v.result();
            h.append("<section class=run id=").append(v.anchor()).append("><h3><a href=#").append(v.rowAnchor())
                    .append(">").append(v.number()).append("</a> ").append(Svg.esc(v.log()))
                    .append(v.run() == null ? "" : ", run " + v.run()).append(": <b>").append(v.verdict())
                    .append("</b>").append(r.lead() == null ? "" : ", lead " + v.duration(r.lead())).append("</h3>")
                    .append(RunPlot.svg(v, t, rule)).append("</section>\n");
        }
        h.append("</div>\n");
    }

    private static String fmt(double d) {
        return String.format(Locale.ROOT, "%.1f", d);
    }

    /** The style sheet, from the class path: it is a file of its own so that it reads and edits as CSS. */
    private static String css() {
        try (InputStream in = HtmlReport.class.getResourceAsStream("report.css")) {
            if (in == null) {
                throw new IllegalStateException("report.css is missing from the class path");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
