package dev.predmon.report;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.SafetyRule;
import dev.predmon.evaluate.Confusion;
import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.RunResult;
import dev.predmon.evaluate.ScenarioSummary;
import dev.predmon.evaluate.Stats;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelStore;
import dev.predmon.parse.Clock;
import org.jfree.chart.JFreeChart;
import org.jfree.svg.SVGGraphics2D;

import java.awt.Rectangle;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * The evaluation as one self-contained HTML file: every chart is inline SVG drawn by JFreeChart through
 * JFreeSVG, the style sheet is inline, there is no script and no external reference, so the file opens
 * anywhere without network. Sections: summary table, confusion matrix, distribution of leads, the battery
 * level of each run over time with its warning and violation marked (the first {@link #MAX_PLOTS} runs), and
 * the learned models drawn ({@link MachineDrawing}) with their DOT text.
 */
public final class HtmlReport {

    /** Runs plotted at most; a page of thousands of charts helps nobody. */
    public static final int MAX_PLOTS = 60;
    private static final int MAX_POINTS = 2000;

    private HtmlReport() {
    }

    /** Writes the report of {@code e} to {@code file}. */
    public static void write(Evaluation e, Abstraction abstraction, Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        Files.writeString(file, html(e, abstraction), StandardCharsets.UTF_8);
    }

    /** The report's text. */
    public static String html(Evaluation e, Abstraction abstraction) throws IOException {
        StringBuilder h = new StringBuilder(1 << 16);
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>predmon evaluation</title>\n")
                .append("<style>body{font-family:sans-serif;margin:2em;max-width:1200px}table{border-collapse:collapse;"
                        + "margin:1em 0}td,th{border:1px solid #bbb;padding:3px 8px;text-align:right}"
                        + "th{background:#eee}td.l,th.l{text-align:left}.run{display:inline-block;margin:4px}"
                        + ".bad{background:#fdd}.good{background:#dfd}svg{max-width:100%;height:auto}"
                        + "pre{background:#f6f6f6;padding:6px;font-size:11px;overflow:auto}"
                        // Machines keep their natural size (readable text) and scroll; on paper they fit the page.
                        + ".machine{overflow:auto;width:max-content;max-width:calc(100vw - 5em);max-height:85vh;"
                        + "border:1px solid #ddd;margin:.5em 0}"
                        + ".machine svg{max-width:none;display:block}.caption{color:#333;max-width:60em}"
                        + "@media print{.machine{overflow:visible;width:auto;max-width:100%;max-height:none;border:0}"
                        + ".machine svg{max-width:100%}.run,svg{break-inside:avoid}}</style></head><body>\n");
        h.append("<h1>predmon evaluation</h1>\n<p>")
                .append(e.mode().equals("cross-validation")
                        ? e.folds() + "-fold cross-validation over the training logs (every run is judged by models "
                        + "learned without it)"
                        : "models learned on the training logs, every run of the test logs judged")
                .append("; threshold ").append(e.threshold()).append("; abstraction <code>")
                .append(esc(e.abstraction())).append("</code>. Each run was replayed through the code path of "
                        + "<code>watch --no-follow</code>, built-in safety monitor included.</p>\n");
        summary(h, e);
        confusion(h, e.confusion());
        for (String n : e.notes()) {
            h.append("<p>Note: ").append(esc(n)).append("</p>\n");
        }
        leads(h, e);
        runs(h, e, abstraction);
        models(h, e);
        h.append("</body></html>\n");
        return h.toString();
    }

    private static void summary(StringBuilder h, Evaluation e) {
        h.append("<h2 id=summary>Summary</h2>\n<table><tr><th class=l>scenario</th><th class=l>kind</th><th>runs</th>"
                + "<th>warned</th><th>hits</th><th>false alarms</th><th>missed</th><th>of which late</th>"
                + "<th>no violation</th><th>no match</th><th>sudden violations</th><th>lead: median [min..max]</th>"
                + "<th>battery at warning: median [min..max]</th></tr>\n");
        for (ScenarioSummary s : e.scenarios()) {
            h.append("<tr><td class=l>").append(esc(s.scenario())).append("</td><td class=l>")
                    .append(s.faulty() ? "faulty" : "nominal").append("</td>");
            for (int v : new int[] {s.runs(), s.warned(), s.hits(), s.falseAlarms(), s.missed(), s.late(),
                    s.noViolation(), s.noMatch()}) {
                h.append("<td>").append(v).append("</td>");
            }
            h.append("<td>").append(s.sudden()).append("</td><td>")
                    .append(s.lead().n() == 0 ? "-" : stats(s.lead()) + " " + s.leadUnit()).append("</td><td>")
                    .append(stats(s.batteryAtWarning())).append("</td></tr>\n");
        }
        h.append("</table>\n<p>Missed: a faulty run without a warning strictly before its violation (late warnings "
                + "included). No violation: a faulty run whose log ends before the property is violated. No match: "
                + "runs during which, at some point, no learned model matched (unknown behaviour). Sudden: "
                + esc(TextReport.sudden(e.runs())) + ".</p>\n");
    }

    private static void confusion(StringBuilder h, Confusion c) {
        h.append("<h2 id=confusion>Confusion matrix</h2>\n<table><tr><th class=l>actual \\ predicted</th>"
                        + "<th>warned before violation</th><th>not warned (in time)</th></tr>\n")
                .append("<tr><th class=l>faulty</th><td class=good>").append(c.truePositives())
                .append("</td><td class=bad>").append(c.falseNegatives()).append("</td></tr>\n")
                .append("<tr><th class=l>nominal</th><td class=bad>").append(c.falsePositives())
                .append("</td><td class=good>").append(c.trueNegatives()).append("</td></tr>\n</table>\n")
                .append("<p>Recall ").append(percent(c.recall())).append(", false-alarm rate ")
                .append(percent(c.falseAlarmRate())).append("; faulty runs without violation, not scored: ")
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
        h.append(svg(ReportCharts.leads(leads, clock), 700, 320, "lead")).append('\n');
    }

    private static void runs(StringBuilder h, Evaluation e, Abstraction abstraction) throws IOException {
        h.append("<h2 id=runs>Runs</h2>\n");
        if (abstraction.safety().isEmpty()) {
            h.append("<p>The abstraction has no safety property, so there is no level to plot.</p>\n");
            return;
        }
        SafetyRule rule = abstraction.safety().get();
        List<RunResult> runs = e.runs();
        if (runs.size() > MAX_PLOTS) {
            h.append("<p>Only the first ").append(MAX_PLOTS).append(" of ").append(runs.size())
                    .append(" runs are plotted; every run is in the JSON output.</p>\n");
        }
        h.append("<p>").append(esc(rule.name())).append(": the watched value over time from the start of the log; "
                + "orange dashed line: the warning; red line: the violation; shaded between them: the lead; grey "
                + "dashed: the bound ").append(fmt(rule.below())).append(".</p>\n");
        int n = 0;
        for (RunResult r : runs) {
            if (n == MAX_PLOTS) {
                break;
            }
            Timeline t = Timeline.ofRun(r.log(), abstraction, rule, MAX_POINTS);
            h.append("<div class=run>").append(svg(ReportCharts.battery(r, t, rule), 540, 260, "run" + n))
                    .append("</div>\n");
            n++;
        }
    }

    private static void models(StringBuilder h, Evaluation e) {
        h.append("<h2 id=models>Learned models</h2>\n<p>")
                .append(e.mode().equals("cross-validation")
                        ? "Learned on every training log (each fold's models are learned on a subset of these runs)."
                        : "Learned on the training logs.")
                .append(" Laid out with ELK's layered algorithm; the initial state is marked by an arrow from nowhere. "
                        + "Labels <code>input</code> (answered OK) and <code>input / output</code>. A large machine "
                        + "scrolls in its box.</p>\n");
        if (e.models() == null) {
            return;
        }
        int n = 0;
        for (LearnedModel m : e.models().models()) {
            MachineGraph folded = MachineGraph.folded(m);
            h.append("<h3>").append(esc(m.id())).append(" (").append(m.faulty() ? "faulty" : "nominal")
                    .append(", ").append(m.machine().size()).append(" states)</h3>\n<p class=caption>")
                    .append(caption(folded)).append("</p>\n<div class=machine>")
                    .append(MachineDrawing.svg(folded, "m" + n + "_")).append("</div>\n");
            if (folded.hidden() > 0) {
                MachineGraph full = MachineGraph.full(m);
                h.append("<details><summary>every state (").append(full.nodes().size()).append(" states, ")
                        .append(full.edges().stream().mapToInt(x -> x.labels().size()).sum())
                        .append(" transitions)</summary><div class=machine>")
                        .append(MachineDrawing.svg(full, "m" + n + "f_")).append("</div></details>\n");
            }
            h.append("<details><summary>DOT</summary><pre>")
                    .append(esc(ModelStore.toDot(m.machine(), m.alphabet()))).append("</pre></details>\n");
            n++;
        }
    }

    /** What the drawing of {@code g} shows of its machine: every state, or which were folded and how. */
    static String caption(MachineGraph g) {
        if (g.hidden() == 0) {
            return "All " + g.states() + " states drawn, one arrow per transition between two states.";
        }
        return g.states() + " states, " + g.nodes().size() + " drawn: the other " + g.hidden() + " only wait for the "
                + "reply to a query (<code>input / OK</code> then <code>Delta / reply</code>), so each such pair is "
                + "drawn as one arrow <code>input / reply</code>. Every state is drawn below, and in the DOT text.";
    }

    private static String svg(JFreeChart chart, int w, int h, String key) {
        SVGGraphics2D g = new SVGGraphics2D(w, h);
        g.setDefsKeyPrefix(key + "_");
        chart.draw(g, new Rectangle(0, 0, w, h));
        return g.getSVGElement(key);
    }

    private static String stats(Stats s) {
        return s.n() == 0 ? "-" : String.format(Locale.ROOT, "%.1f [%.1f..%.1f]", s.median(), s.min(), s.max());
    }

    private static String percent(Double d) {
        return d == null ? "-" : String.format(Locale.ROOT, "%.1f%%", d * 100);
    }

    private static String fmt(double d) {
        return String.format(Locale.ROOT, "%.1f", d);
    }

    private static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
