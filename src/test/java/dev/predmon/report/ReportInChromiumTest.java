package dev.predmon.report;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.Evaluator;
import dev.predmon.evaluate.Progress;
import dev.predmon.evaluate.Verdict;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.support.BrowserTabs;
import dev.predmon.support.HeadlessChromium;
import dev.predmon.support.RealLogs;
import dev.predmon.support.SimulatedSets;
import dev.predmon.support.SvgTexts;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The evaluate report as a reader sees it, rendered in headless Chromium: no two texts of any drawing overlap,
 * in the plots or in the drawn machines (every shipped model's, folded and in full); the table of runs has a row
 * per run whose link brings that run's plot into view, and back; a machine wider than the page fits it until
 * "full size" is ticked. Skipped, with a message, where no Chromium is installed.
 */
@Timeout(300)
class ReportInChromiumTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Set<String> VERDICTS = Set.of("warned ahead", "warned too late", "violated without warning",
            "false alarm", "no model matches", "warned, held", "held");

    @TempDir
    static Path dir;
    @RegisterExtension
    static final BrowserTabs TABS = new BrowserTabs(1400, 1000);
    private static final String UNTESTED = "the report is not rendered; MachineLayoutTest and HtmlReportTest still "
            + "check the layouts and the page";
    private static Evaluation sample;

    private static void assumeChromium() {
        TABS.assumeBrowser(UNTESTED);
    }

    /** The shipped sample logs, evaluated by 5-fold cross-validation (once for the tests that show them). */
    private static synchronized Evaluation sample() throws Exception {
        if (sample == null) {
            Abstraction a = AbstractionFiles.defaults();
            sample = new Evaluator(a, 0, Progress.NONE).crossValidate(ScenarioLayout.scan(Path.of("sample-logs"), a), 5);
        }
        return sample;
    }

    private static HeadlessChromium.Page open(String name, String html) throws Exception {
        Path file = Files.writeString(dir.resolve(name), html, StandardCharsets.UTF_8);
        HeadlessChromium.Page page = TABS.open(file.toUri(), UNTESTED);
        SvgTexts.loaded(page);
        return page;
    }

    @Test
    void noTextOverlapsAnotherInTheRenderedReportWithEveryShippedModel() throws Exception {
        assumeChromium();
        Path logs = SimulatedSets.write(dir.resolve("logs"), 2, 1);
        Evaluation e = new Evaluator(AbstractionFiles.defaults(), 0, Progress.NONE)
                .crossValidate(ScenarioLayout.scan(logs, AbstractionFiles.defaults()), 2);
        ModelSet shipped = ModelStore.read(Path.of("models"), AbstractionFiles.defaults());
        Evaluation withShipped = new Evaluation(e.mode(), e.folds(), e.tolerance(), e.abstraction(), e.scenarios(),
                e.confusion(), e.runs(), e.notes(), shipped);

        SvgTexts.Measured m = SvgTexts.measure(open("shipped.html", HtmlReport.html(withShipped, AbstractionFiles.defaults())));

        assertEquals(List.of(), m.overlaps(), "overlapping texts (svg, text, text)");
        int drawings = 0;
        long machineTexts = 0;
        for (LearnedModel model : shipped.models()) {
            MachineGraph folded = MachineGraph.folded(model);
            drawings += folded.hidden() > 0 ? 2 : 1;
            machineTexts += texts(folded) + (folded.hidden() > 0 ? texts(MachineGraph.full(model)) : 0);
        }
        int charts = e.runs().size() + (e.runs().stream().anyMatch(r -> r.lead() != null) ? 1 : 0)
                + (withShipped.forecast() != null ? 1 : 0); // the threshold sweep
        assertEquals(drawings + charts, m.svgs(), "every chart and machine drawing rendered");
        assertTrue(m.texts() > machineTexts, m.texts() + " texts measured, the machines alone have " + machineTexts);
    }

    /** The real recordings: runs counted in ticks, violations far from their warning, machines learned from them. */
    @Test
    void noTextOverlapsAnotherInTheReportOfTheRealRecordings() throws Exception {
        assumeChromium();
        assumeTrue(Files.isDirectory(RealLogs.DIR), "no " + RealLogs.DIR + ", so its report is not rendered");
        Abstraction a = AbstractionFiles.builtin("scope-fetch").orElseThrow();
        Evaluation e = new Evaluator(a, 0, Progress.NONE).crossValidate(ScenarioLayout.scan(RealLogs.DIR, a), 5);
        SvgTexts.Measured m = SvgTexts.measure(open("real.html", HtmlReport.html(e, a)));
        assertEquals(List.of(), m.overlaps(), "overlapping texts (svg, text, text)");
        assertTrue(m.svgs() > e.runs().size(), m.svgs() + " drawings for " + e.runs().size() + " runs");
    }

    @Test
    void theCheckFindsTheOverlappingLabelsOfTheDrawingBeforeIssue12() throws Exception {
        assumeChromium();
        String old = Files.readString(Path.of("src/test/resources/report/old-recharge-2.svg"), StandardCharsets.UTF_8);
        SvgTexts.Measured m = SvgTexts.measure(open("old.html", "<!DOCTYPE html><html><body>" + old + "</body></html>"));
        assertEquals(1, m.svgs());
        assertTrue(m.overlaps().stream().anyMatch(o -> o.contains("batteryStatus_i / o_batteryStatus_false")
                && o.contains("batteryStatus_i / o_batteryStatus_true")), String.join("\n", m.overlaps()));
    }

    /**
     * The report of the shipped sample logs (every verdict but a late warning and a miss happens there): one row
     * per run, every row's link brings its run's plot to the top of the window, the plot links back to the row,
     * and verdicts read in words. Saves what the window shows of the table, from just before the first run no
     * model matched, to {@code target/report-runs.png}.
     */
    @Test
    void everyRunIsOneClickFromItsRowToItsPlotAndBack() throws Exception {
        assumeChromium();
        Evaluation e = sample();
        HeadlessChromium.Page page = open("sample.html", HtmlReport.html(e, AbstractionFiles.defaults()));

        JsonNode rows = JSON.readTree(page.eval("JSON.stringify([...document.querySelectorAll('table.runs tbody tr')]"
                + ".map(r => ({id: r.id, href: r.querySelector('a').getAttribute('href'),"
                + " verdict: r.querySelector('td.v').firstChild.textContent,"
                + " target: !!document.querySelector(r.querySelector('a').getAttribute('href') + ' svg.plot'),"
                + " back: (document.querySelector(r.querySelector('a').getAttribute('href') + ' h3 a') || {})"
                + ".getAttribute ? document.querySelector(r.querySelector('a').getAttribute('href') + ' h3 a')"
                + ".getAttribute('href') : null})))"));
        assertEquals(e.runs().size(), rows.size(), "one row per run");
        for (JsonNode r : rows) {
            assertTrue(r.get("target").asBoolean(), "the row links to a plot: " + r);
            assertEquals("#" + r.get("id").asText(), r.get("back").asText(), "the plot links back to its row: " + r);
            assertTrue(VERDICTS.contains(r.get("verdict").asText()), "a verdict in words: " + r);
        }
        assertTrue(rows.findValuesAsText("verdict").contains("no model matches"), rows.toString());

        // The rows of the recharge runs, from one before the first no-match: most verdicts of the sample, under the header.
        page.eval("(() => { const rows = [...document.querySelectorAll('table.runs tbody tr')];"
                + " const i = rows.findIndex(r => r.querySelector('td.v').firstChild.textContent === 'no model matches');"
                + " rows[Math.max(0, i - 1)].scrollIntoView(); return ''; })()");
        page.screenshot(Path.of("target", "report-runs.png"));

        // One click on the row of a run no model matched: its plot comes to the top of the window, framed.
        String top = page.eval("(() => { const row = [...document.querySelectorAll('table.runs tbody tr')]"
                + ".find(r => r.querySelector('td.v').firstChild.textContent === 'no model matches');"
                + " row.querySelector('a').click();"
                + " const plot = document.querySelector(location.hash);"
                + " return JSON.stringify({hash: location.hash, top: plot.getBoundingClientRect().top,"
                + " framed: plot.matches(':target'), label: plot.querySelector('.mnomatch').textContent}); })()");
        JsonNode clicked = JSON.readTree(top);
        assertTrue(clicked.get("hash").asText().startsWith("#run-"), clicked.toString());
        assertTrue(Math.abs(clicked.get("top").asDouble()) < 2, "the plot is at the top of the window: " + clicked);
        assertTrue(clicked.get("framed").asBoolean(), clicked.toString());
        assertTrue(clicked.get("label").asText().startsWith("no model matches from "), clicked.toString());
    }

    /**
     * The report of the shipped sample logs as a reader sees it: each run's plot draws the forecast's probability
     * beside the value, and the threshold sweep is a chart whose two lines are drawn. Saves the sweep with the first
     * plots to {@code target/report-forecast.png} (the picture in {@code docs/report.png}) and the first plots to
     * {@code target/report-plots.png} ({@code docs/report-plots.png}).
     */
    @Test
    void theForecastIsDrawnBesideTheValueAndTheSweepAsAChart() throws Exception {
        assumeChromium();
        Evaluation e = sample();
        HeadlessChromium.Page page = open("forecast.html", HtmlReport.html(e, AbstractionFiles.defaults()));
        JsonNode drawn = JSON.readTree(page.eval("JSON.stringify({plots: document.querySelectorAll('svg.plot:not(.sweep)"
                + ":not(.hist)').length, probs: [...document.querySelectorAll('svg.plot path.prob')]"
                + ".filter(p => p.getTotalLength() > 0 && p.getBoundingClientRect().width > 0).length,"
                + " recall: document.querySelector('svg.sweep path.recall').getTotalLength(),"
                + " alarms: document.querySelector('svg.sweep path.alarms').getTotalLength(),"
                + " firstVerdict: document.querySelector('table.runs tbody td.v').firstChild.textContent})"));
        assertEquals(e.runs().size(), drawn.get("plots").asInt(), drawn.toString());
        long forecast = e.runs().stream().filter(r -> r.forecast().times().stream().distinct().count() > 1).count();
        assertTrue(forecast > e.runs().size() / 2, forecast + " runs with a forecast");
        assertEquals(forecast, drawn.get("probs").asLong(), "a probability drawn in every plot that has one: " + drawn);
        assertTrue(drawn.get("recall").asDouble() > 100 && drawn.get("alarms").asDouble() > 100, drawn.toString());
        boolean wrong = e.runs().stream().anyMatch(r -> r.verdict() == Verdict.FALSE_ALARM
                || r.verdict() == Verdict.MISSED || r.verdict() == Verdict.WARNED_LATE);
        assertTrue(!wrong || Set.of("false alarm", "violated without warning", "warned too late")
                .contains(drawn.get("firstVerdict").asText()), "what went wrong comes first: " + drawn);
        page.eval("(() => { document.getElementById('sweep').scrollIntoView(); return ''; })()");
        page.screenshot(Path.of("target", "report-forecast.png"));
        page.eval("(() => { document.querySelector('.plots').scrollIntoView(); return ''; })()");
        page.screenshot(Path.of("target", "report-plots.png"));
    }

    @Test
    void aMachineWiderThanThePageFitsItUntilFullSizeIsTicked() throws Exception {
        assumeChromium();
        MachineLayout wide = MachineLayout.of(MachineGraph.full(MachineLayoutTest.random(60, 7)));
        assumeTrue(wide.width() > MachineLayout.PAGE_WIDTH, "the random machine is " + wide.width() + " wide");
        StringBuilder h = new StringBuilder("<!DOCTYPE html><html><head><style>")
                .append(Files.readString(Path.of("src/main/resources/dev/predmon/report/report.css")))
                .append("</style></head><body>");
        h.append("<input type=checkbox class=zoom id=z0><label for=z0>full size</label><div class=machine>")
                .append(MachineDrawing.svg(wide)).append("</div></body></html>");
        HeadlessChromium.Page page = open("wide.html", h.toString());
        String width = "String(document.querySelector('svg.mealy').getBoundingClientRect().width)";
        double fitted = Double.parseDouble(page.eval(width));
        double window = Double.parseDouble(page.eval("String(document.documentElement.clientWidth)"));
        assertTrue(fitted < window && fitted < wide.width() / 2, "scaled to the page: " + fitted);
        page.eval("(() => { document.querySelector('label').click(); return ''; })()");
        assertEquals(Math.ceil(wide.width()), Double.parseDouble(page.eval(width)), 1, "at full size");
        assertFalse(page.eval("String(document.querySelector('.machine').scrollWidth)").equals(
                page.eval("String(document.querySelector('.machine').clientWidth)")), "the box scrolls");
    }

    private static long texts(MachineGraph g) {
        return g.nodes().size() + g.edges().stream().mapToLong(x -> x.drawn().size()).sum();
    }
}
