package dev.predmon.report;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.evaluate.RunResult;
import dev.predmon.parse.Clock;
import dev.predmon.pipeline.RunId;
import dev.predmon.property.Bound;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The report's plots as SVG text: times from the start of the run, round ticks, labels apart, curves thinned. */
class RunPlotTest {

    private static final Bound RULE = AbstractionFiles.defaults().safety().orElseThrow();
    private static final Pattern TEXT = Pattern.compile(
            "<text class=\"([^\"]+)\" x=\"([-0-9.]+)\" y=\"([-0-9.]+)\">([^<]*)</text>");

    @TempDir
    Path dir;

    /** A text of a plot: its content and its box, from its anchor, baseline and measured width. */
    private record Drawn(String cls, String text, double x, double top, double w, double h) {
        boolean overlaps(Drawn o) {
            return x < o.x + o.w && o.x < x + w && top < o.top + o.h && o.top < top + h;
        }
    }

    private static List<Drawn> texts(String svg) {
        List<Drawn> out = new ArrayList<>();
        Matcher m = TEXT.matcher(svg);
        while (m.find()) {
            String cls = m.group(1);
            boolean bold = cls.startsWith("m") || cls.equals("xl");
            double w = Svg.width(m.group(4), bold);
            double x = Double.parseDouble(m.group(2));
            double left = cls.contains("end") || cls.equals("ty") ? x - w : cls.equals("tx") || cls.equals("xl") ? x - w / 2 : x;
            // A browser's box of an 11 px sans-serif text: its ascent above the baseline, its descent below.
            out.add(new Drawn(cls, m.group(4), left, Double.parseDouble(m.group(3)) - 10.2, w, 12.8));
        }
        return out;
    }

    private static Drawn only(List<Drawn> texts, String cls) {
        List<Drawn> found = texts.stream().filter(t -> t.cls().startsWith(cls)).toList();
        assertEquals(1, found.size(), cls + " in " + texts);
        return found.get(0);
    }

    /** A run starting at {@code start}, warned and violated at those times from its start (null: not at all). */
    private static RunView run(double start, Double warning, Double violation, Double noMatch, Clock clock) {
        RunResult r = JudgedRuns.run("logs/depleted/depleted-1.log", true, warning, violation, noMatch, 0);
        double shift = start - JudgedRuns.START;
        RunResult moved = new RunResult(r.scenario(), true, r.log(), 0, r.verdict(), shift(r.warningTime(), shift),
                r.warningLine(), r.warningScenarios(), r.valueAtWarning(), shift(r.violationTime(), shift), r.lead(),
                r.noMatch(), shift(r.noMatchTime(), shift), 1, 1, 0, List.of(), true, clock.unit(), false, start, 0, null);
        return RunView.of(1, moved);
    }

    private static Double shift(Double t, double by) {
        return t == null ? null : t + by;
    }

    @Test
    void anEpochLogIsPlottedFromTheStartOfTheRun() throws Exception {
        Path log = dir.resolve("epoch.log");
        SimOptions epoch = SimOptions.defaults().withEpoch(true);
        Files.writeString(log, LogWriter.toText(Simulator.run(Scenario.DEPLETED, 3, epoch), epoch));
        Timeline t = Timeline.ofRun(RunId.of(log, 0, 1), AbstractionFiles.defaults(), RULE, 20_000);
        assertTrue(t.start() > 1e9, "epoch start " + t.start());
        List<Drawn> texts = texts(RunPlot.svg(run(t.start(), 20.0, 25.0, null, t.clock()), t, RULE));
        assertEquals("time (s from start)", only(texts, "xl").text());
        for (Drawn d : texts) {
            assertFalse(d.text().matches(".*[0-9,.]{7,}.*"), "epoch-sized text " + d.text());
        }
        assertTrue(texts.stream().anyMatch(d -> d.cls().equals("tx") && d.text().equals("0")), texts.toString());
        assertEquals("warning 20.0 s", only(texts, "mwarn").text());
    }

    @Test
    void aLogCountedInTicksSaysSoAndHasWholeTicks() {
        Timeline t = new Timeline(100, new double[] {100, 101, 102, 103, 104, 105},
                new double[] {60, 50, 40, 30, 20, 10}, Clock.TICKS);
        List<Drawn> texts = texts(RunPlot.svg(run(100, 2.0, 4.0, null, Clock.TICKS), t, RULE));
        assertEquals("time (ticks from start)", only(texts, "xl").text());
        List<Drawn> ticks = texts.stream().filter(d -> d.cls().equals("tx")).toList();
        assertTrue(ticks.size() >= 2, texts.toString());
        for (Drawn d : ticks) {
            assertTrue(d.text().matches("\\d+"), "a whole tick: " + d.text());
        }
        assertEquals("violation 4 ticks", only(texts, "mviol").text());
    }

    @Test
    void markerLabelsNeverOverlapAnotherTextHoweverCloseTheirLines() {
        Timeline t = new Timeline(0, new double[] {0, 10, 20, 30, 40}, new double[] {90, 70, 40, 19, 5}, Clock.SECONDS);
        for (double[] wvn : new double[][] {{29.9, 30, 30}, {30, 30, 30}, {39.9, 40, 40}, {0, 0.05, 0.1}, {1, 40, 20}}) {
            List<Drawn> texts = texts(RunPlot.svg(run(0, wvn[0], wvn[1], wvn[2], Clock.SECONDS), t, RULE));
            for (String cls : List.of("mwarn", "mviol", "mnomatch")) {
                Drawn m = only(texts, cls); // the one text of its class: o is m when o is of cls
                assertTrue(m.x() >= 0 && m.x() + m.w() <= RunPlot.WIDTH, m + " inside the plot");
                for (Drawn o : texts) {
                    assertTrue(o.cls().startsWith(cls) || !m.overlaps(o), m + " overlaps " + o);
                }
            }
        }
    }

    /** The forecast's probability on its own scale at the right: steps at the times of the forecasts, the threshold. */
    @Test
    void theForecastsProbabilityIsDrawnOnItsOwnScale() {
        Timeline t = new Timeline(0, new double[] {0, 10, 20, 30, 40}, new double[] {90, 70, 40, 19, 5}, Clock.SECONDS);
        RunView plain = run(0, 20.0, 30.0, null, Clock.SECONDS);
        RunResult r = plain.result();
        RunResult.ForecastTrace f = new RunResult.ForecastTrace(List.of(0.2, 0.2, 0.9), null, null, 0.25, 0.6, null,
                List.of(0.0, 10.0, 20.0));
        RunView withP = RunView.of(1, new RunResult(r.scenario(), r.faulty(), r.log(), r.fold(), r.verdict(),
                r.warningTime(), r.warningLine(), r.warningScenarios(), r.valueAtWarning(), r.violationTime(),
                r.lead(), r.noMatch(), r.noMatchTime(), r.records(), r.pairs(), r.problems(), r.eliminations(),
                r.safetyObserved(), r.unit(), r.sudden(), r.start(), r.nearBound(), r.beforeViolation(), f));
        assertFalse(RunPlot.svg(plain, t, RULE).contains("class=\"prob\""), "no forecast, no probability");
        String svg = RunPlot.svg(withP, t, RULE);
        double bottom = RunPlot.HEIGHT - Axis.BOTTOM;
        double top = 46;
        Matcher prob = Pattern.compile("<path class=\"prob\" d=\"([^\"]*)\"").matcher(svg);
        assertTrue(prob.find(), svg);
        List<Double> ys = new ArrayList<>();
        Matcher point = Pattern.compile("[ML]([-0-9.]+) ([-0-9.]+)").matcher(prob.group(1));
        while (point.find()) {
            ys.add(Double.parseDouble(point.group(2)));
        }
        double at02 = bottom - 0.2 * (bottom - top);
        double at09 = bottom - 0.9 * (bottom - top);
        assertEquals(at02, ys.get(0), 0.01, "it starts at 0.2: " + prob.group(1));
        assertEquals(at09, ys.get(ys.size() - 1), 0.01, "and ends at 0.9: " + prob.group(1));
        List<Double> step = List.of(at02, at02, at09).stream().map(y -> Double.parseDouble(Svg.num(y))).toList();
        assertEquals(step, ys, "a step: 0.2 until the third forecast, then 0.9");
        assertTrue(svg.contains("<path class=\"pthr\" d=\"M50 " + Svg.num(bottom - 0.6 * (bottom - top)) + "H"), svg);
        List<Drawn> texts = texts(svg);
        assertEquals(List.of("0", "0.5", "1"), texts.stream().filter(d -> d.cls().equals("tp")).map(Drawn::text).toList());
        for (int i = 0; i < texts.size(); i++) {
            Drawn a = texts.get(i);
            assertTrue(a.x() + a.w() <= RunPlot.WIDTH, a + " inside the plot");
            for (Drawn b : texts.subList(i + 1, texts.size())) {
                assertFalse(a.overlaps(b), a + " overlaps " + b);
            }
        }
    }

    @Test
    void aLongRunIsThinnedToWhatThePlotCanShow() {
        int n = 20_000;
        double[] times = new double[n];
        double[] line = new double[n];
        double[] steps = new double[n];
        for (int i = 0; i < n; i++) {
            times[i] = i * 0.05;
            line[i] = 100 - i * 90.0 / n;
            steps[i] = 100 - 10 * Math.floor(i / 2000.0);
        }
        String straight = RunPlot.svg(run(0, null, null, null, Clock.SECONDS), new Timeline(0, times, line, Clock.SECONDS), RULE);
        String path = straight.replaceAll("(?s).*<path class=\"val\" d=\"([^\"]*)\".*", "$1");
        assertTrue(path.split("L").length <= 3, "a straight decline is a line: " + path);
        String stepped = RunPlot.svg(run(0, null, null, null, Clock.SECONDS), new Timeline(0, times, steps, Clock.SECONDS), RULE);
        String stepPath = stepped.replaceAll("(?s).*<path class=\"val\" d=\"([^\"]*)\".*", "$1");
        // Ten steps: each a level and a drop, so about two points a step, not two thousand.
        int points = stepPath.split("L").length;
        assertTrue(points >= 19 && points <= 40, points + " points: " + stepPath);
        assertTrue(stepped.length() < 4000, stepped.length() + " characters");
    }

    @Test
    void theLeadHistogramCountsWholeRunsInRoundBins() {
        String svg = LeadHistogram.svg(new double[] {3.4, 3.9, 3.8, 5.1, 8.7, 8.5, 12.2, 11.9, 17.0, 19.0}, Clock.SECONDS);
        List<Drawn> texts = texts(svg);
        // Two leads far from 0, as on the real recordings: the x axis starts at 45, beside the y axis's 0.
        List<Drawn> far = texts(LeadHistogram.svg(new double[] {48, 83}, Clock.TICKS));
        for (int i = 0; i < far.size(); i++) {
            for (int j = i + 1; j < far.size(); j++) {
                assertFalse(far.get(i).overlaps(far.get(j)), far.get(i) + " overlaps " + far.get(j));
            }
        }
        for (Drawn d : texts.stream().filter(d -> d.cls().equals("ty")).toList()) {
            assertTrue(d.text().matches("\\d+"), "a whole number of runs: " + d.text());
        }
        assertEquals("lead (s)", only(texts, "xl").text());
        for (int i = 0; i < texts.size(); i++) {
            for (int j = i + 1; j < texts.size(); j++) {
                assertFalse(texts.get(i).overlaps(texts.get(j)), texts.get(i) + " overlaps " + texts.get(j));
            }
        }
        assertEquals(1, LeadHistogram.binWidth(15.6));
        assertEquals(1, LeadHistogram.binWidth(20));
        assertEquals(2, LeadHistogram.binWidth(21));
        assertEquals(0.5, LeadHistogram.binWidth(7), 1e-12);
        assertEquals(50, LeadHistogram.binWidth(900));
        assertEquals(1, LeadHistogram.binWidth(0));
    }
}
