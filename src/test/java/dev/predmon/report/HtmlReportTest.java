package dev.predmon.report;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.Evaluator;
import dev.predmon.evaluate.ForecastScore;
import dev.predmon.evaluate.Progress;
import dev.predmon.evaluate.RunResult;
import dev.predmon.forecast.Forecast;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.support.SimulatedSets;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The report page as text: self-contained, one plot and one table row per run linked both ways, its style sheet
 * and drawing definitions once, and under a megabyte for a hundred runs.
 */
class HtmlReportTest {

    @TempDir
    static Path dir;
    /** 102 runs: 34 of each simulated scenario. */
    static Evaluation hundred;
    static String html;

    @BeforeAll
    static void evaluate() throws Exception {
        Path logs = SimulatedSets.write(dir.resolve("logs"), 34, 1);
        hundred = new Evaluator(AbstractionFiles.defaults(), 0, Progress.NONE)
                .crossValidate(ScenarioLayout.scan(logs, AbstractionFiles.defaults()), 5);
        html = HtmlReport.html(hundred, AbstractionFiles.defaults());
    }

    private static List<String> all(String regex, String text) {
        List<String> found = new ArrayList<>();
        Matcher m = Pattern.compile(regex).matcher(text);
        while (m.find()) {
            found.add(m.groupCount() > 0 ? m.group(1) : m.group());
        }
        return found;
    }

    @Test
    void aHundredRunsTakeLessThanAMegabyte() {
        assertTrue(hundred.runs().size() >= 100, hundred.runs().size() + " runs");
        int bytes = html.getBytes(StandardCharsets.UTF_8).length;
        assertTrue(bytes < 1_000_000, bytes + " bytes for " + hundred.runs().size() + " runs");
    }

    @Test
    void theReportIsSelfContained() {
        assertFalse(Pattern.compile("(src|href)\\s*=\\s*[\"']?https?:", Pattern.CASE_INSENSITIVE).matcher(html).find());
        assertFalse(html.contains("<script"));
        assertFalse(html.contains("<link"));
        assertTrue(html.contains("Confusion matrix"));
        assertTrue(html.contains("Learned models"));
    }

    @Test
    void stylesAndDefinitionsAreOnThePageOnceNotInEveryDrawing() {
        assertEquals(1, all("<style>", html).size());
        assertEquals(1, all("<marker ", html).size(), "one arrowhead for every machine");
        assertEquals(1, all("<defs>", html).size());
        assertEquals(List.of(), all("<svg[^>]* style=\"[^\"]*\"", html), "no drawing styles itself");
        assertFalse(html.contains("stroke=\"") || html.contains("fill=\"#") || html.contains("font-size=\""),
                "colours and fonts are the style sheet's");
    }

    @Test
    void everyRunHasARowAndAPlotThatLinkToEachOther() {
        List<String> rows = all("<tr id=(row-\\d+)", html);
        List<String> plots = all("<section class=run id=(run-\\d+)", html);
        assertEquals(hundred.runs().size(), rows.size());
        assertEquals(hundred.runs().size(), plots.size());
        Set<String> ids = new HashSet<>(rows);
        ids.addAll(plots);
        assertEquals(rows.size() + plots.size(), ids.size(), "ids are unique");
        for (String link : all("href=#?\"?#((?:row|run)-\\d+)", html)) {
            assertTrue(ids.contains(link), "a link to nowhere: #" + link);
        }
        assertEquals(hundred.runs().size(), all("<svg class=\"plot\"", html).size(), "one plot per run");
    }

    @Test
    void everyOtherPropertyHasARowWithItsBaselineBesideIt() {
        List<dev.predmon.evaluate.PropertyScore> scores = dev.predmon.evaluate.PropertyScore.of(hundred.runs());
        assertFalse(scores.isEmpty(), "the built-in abstraction has other properties");
        assertTrue(html.contains("<h2 id=properties>The other properties</h2>"));
        for (dev.predmon.evaluate.PropertyScore p : scores) {
            assertTrue(html.contains("<tr><td>" + p.property() + "</td><td>" + p.runs() + "</td><td>" + p.noEvidence()
                    + "</td><td>" + p.violating()
                    + "</td><td>" + p.warned() + "</td><td>" + p.falseAlarms() + "</td>"), p.property());
        }
        assertTrue(html.contains("baseline: warned ahead"));
    }

    @Test
    void theSuddenNoteSaysWhatTheDataShow() {
        long sudden = hundred.runs().stream().filter(RunResult::sudden).count();
        String note = TextReport.sudden(hundred.runs());
        assertTrue(note.startsWith("a violation with fewer than 10 readings within 10 points above the bound"), note);
        assertTrue(note.contains(" of the " + sudden + " sudden violations here were still warned ahead"), note);
        assertTrue(html.contains(Svg.esc(note)));
        assertFalse(html.contains("no monitor can see"), "a sudden violation the models warned of was foreseen");
    }

    @Test
    void theForecastColumnShowsAForecastWhereTheRunHasOne() {
        RunResult r = JudgedRuns.oneOfEach().get(0);
        RunResult warned = withForecast(r, new RunResult.ForecastTrace(List.of(0.3, 0.82), null,
                new Forecast(0.82, 12.5, 8.0, 20.0, Forecast.Basis.MATCHED, null, 12, 10, 28.7, -0.8, "s"), 0.3, 0.6));
        RunResult quiet = withForecast(JudgedRuns.oneOfEach().get(5),
                new RunResult.ForecastTrace(List.of(0.1, 0.4, 0.2), null, null, 0.3, 0.6));
        StringBuilder h = new StringBuilder();
        RunTable.html(h, List.of(RunView.of(1, r), RunView.of(2, warned), RunView.of(3, quiet)), 0);
        List<String> cells = all("<td class=forecast>([^<]*)</td>", h.toString());
        assertEquals(List.of(RunView.NONE, "82%, in 12.5 s", "max 40%"), cells);
    }

    /** Each forecast of a replayed run has the time it was made at: within the run, in order, before any violation. */
    @Test
    void everyForecastHasItsTimeAndEveryPlotDrawsTheProbability() {
        int withForecast = 0;
        for (RunResult r : hundred.runs()) {
            RunResult.ForecastTrace f = r.forecast();
            assertEquals(f.probabilities().size(), f.times().size(), r.log().name());
            double before = r.start();
            for (double t : f.times()) {
                assertTrue(t >= before, r.log() + ": " + f.times());
                assertTrue(r.violationTime() == null || t <= r.violationTime(), r.log() + ": after the violation");
                before = t;
            }
            withForecast += f.times().isEmpty() ? 0 : 1;
        }
        assertTrue(withForecast > 90, withForecast + " runs with a forecast");
        assertEquals(withForecast, all("<path class=\"prob\"", html).size(), "the probability in every such plot");
        assertEquals(withForecast, all("<path class=\"pthr\"", html).size(), "and its threshold");
        assertTrue(html.contains("P(violation)</text>"));
    }

    /** The sweep is drawn: a line each for the violations warned and the false alarms, a point per threshold. */
    @Test
    void theThresholdSweepIsAChart() {
        String chart = all("(<svg class=\"plot sweep\".*?</svg>)", html).get(0);
        String recall = all("<path class=\"recall\" d=\"([^\"]*)\"", chart).get(0);
        String alarms = all("<path class=\"alarms\" d=\"([^\"]*)\"", chart).get(0);
        int points = hundred.forecast().sweep().size();
        assertEquals(points, all("[ML]", recall).size(), recall);
        assertEquals(points, all("[ML]", alarms).size(), alarms);
        // every simulated depleted run is warned at 0.1; the y of 100% is the top of the plot
        ForecastScore.Point low = hundred.forecast().sweep().get(0);
        assertEquals(low.violating(), low.warned(), low.toString());
        assertTrue(recall.startsWith("M" + Svg.num(50 + 0.1 * (SweepChart.WIDTH - 16 - 50)) + " 46"), recall);
        assertTrue(chart.contains("threshold chosen") || chart.contains("thresholds chosen"), chart);
        assertTrue(html.contains("<td>0.9</td>"), "the numbers stay beside the chart");
    }

    /** Missed violations, then false alarms, then runs no model matched, then the rest, each in the order given. */
    @Test
    void theRunsThatWentWrongComeFirst() {
        List<RunResult> given = JudgedRuns.oneOfEach();
        List<RunResult> sorted = HtmlReport.firstWhatWentWrong(given);
        StringBuilder h = new StringBuilder();
        List<RunView> views = new ArrayList<>();
        for (RunResult r : sorted) {
            views.add(RunView.of(views.size() + 1, r));
        }
        RunTable.html(h, views, 0);
        assertEquals(List.of("warned too late", "violated without warning", "false alarm", "no model matches",
                "warned ahead", "held"), all("<td class=\"l v\">([^<]*)", h.toString()));
        // the hundred simulated runs: whatever went wrong is at the top of the page's table
        List<String> verdicts = all("<td class=\"l v\">([^<]*)", html);
        int firstFine = verdicts.indexOf("warned ahead");
        for (int i = firstFine; i < verdicts.size(); i++) {
            assertFalse(Set.of("violated without warning", "warned too late", "false alarm").contains(verdicts.get(i)),
                    i + ": " + verdicts);
        }
    }

    private static RunResult withForecast(RunResult r, RunResult.ForecastTrace f) {
        return new RunResult(r.scenario(), r.faulty(), r.log(), r.fold(), r.verdict(), r.warningTime(), r.warningLine(),
                r.warningScenarios(), r.valueAtWarning(), r.violationTime(), r.lead(), r.noMatch(), r.noMatchTime(),
                r.records(), r.pairs(), r.problems(), r.eliminations(), r.safetyObserved(), r.unit(), r.sudden(),
                r.start(), r.nearBound(), r.beforeViolation(), f);
    }
}
