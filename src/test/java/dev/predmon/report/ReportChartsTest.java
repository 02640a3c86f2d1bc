package dev.predmon.report;

import dev.predmon.evaluate.RunResult;
import dev.predmon.evaluate.Verdict;
import dev.predmon.parse.Clock;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.SafetyRule;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.jfree.chart.JFreeChart;
import org.jfree.svg.SVGGraphics2D;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.awt.Font;
import java.awt.Rectangle;
import java.awt.font.FontRenderContext;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The report's charts, drawn to SVG as the report draws them, and read back from the SVG. */
class ReportChartsTest {

    private static final SafetyRule RULE = Abstraction.defaults().safety().orElseThrow();
    private static final Pattern TEXT = Pattern.compile(
            "<text x='([-0-9.E]+)' y='([-0-9.E]+)' style='[^']*font-size: (\\d+)px;[^']*'[^>]*>([^<]*)</text>");
    private static final FontRenderContext FRC = new FontRenderContext(null, true, true);

    @TempDir
    Path dir;

    /** A text of a drawn chart: its content and its box (from its baseline, font size and measured width). */
    private record Drawn(String text, double x, double top, double w, double h) {
        boolean overlaps(Drawn o) {
            return x < o.x + o.w && o.x < x + w && top < o.top + o.h && o.top < top + h;
        }
    }

    private static List<Drawn> texts(JFreeChart chart, int w, int h) {
        SVGGraphics2D g = new SVGGraphics2D(w, h);
        chart.draw(g, new Rectangle(0, 0, w, h));
        List<Drawn> out = new ArrayList<>();
        Matcher m = TEXT.matcher(g.getSVGElement());
        while (m.find()) {
            int size = Integer.parseInt(m.group(3));
            Font f = new Font(Font.SANS_SERIF, Font.BOLD, size);
            double width = f.getStringBounds(m.group(4), FRC).getWidth();
            double y = Double.parseDouble(m.group(2));
            out.add(new Drawn(m.group(4), Double.parseDouble(m.group(1)), y - size, width, size * 1.2));
        }
        return out;
    }

    private static String svg(JFreeChart chart) {
        SVGGraphics2D g = new SVGGraphics2D(560, 260);
        chart.draw(g, new Rectangle(0, 0, 560, 260));
        return g.getSVGElement();
    }

    private static RunResult run(Double warning, Double violation) {
        Double lead = warning != null && violation != null && warning < violation ? violation - warning : null;
        return new RunResult("depleted", true, "depleted-1.log", -1, Verdict.of(true, warning, violation), warning,
                warning == null ? null : 100L, List.of("depleted"), 28.0, violation, lead, false, null, 1, 1, 0,
                List.of(), true, "s", false, 0.0, 20);
    }

    private static Drawn only(List<Drawn> texts, String s) {
        List<Drawn> found = texts.stream().filter(t -> t.text().equals(s)).toList();
        assertEquals(1, found.size(), s + " in " + texts);
        return found.get(0);
    }

    @Test
    void anEpochLogIsPlottedFromTheStartOfTheRun() throws Exception {
        Path log = dir.resolve("epoch.log");
        SimOptions epoch = SimOptions.defaults().withEpoch(true);
        Files.writeString(log, LogWriter.toText(Simulator.run(Scenario.DEPLETED, 3, epoch), epoch));
        Timeline t = Timeline.read(log, RULE, 2000);
        assertTrue(t.start() > 1e9, "epoch start " + t.start());
        assertTrue(t.times()[0] >= t.start());
        double end = t.sinceStart(t.times()[t.times().length - 1]);
        assertTrue(end > 10 && end < 1000, "run length " + end);

        List<Drawn> texts = texts(ReportCharts.battery(run(t.times()[0] + 20, t.times()[0] + 25), t, RULE), 560, 260);
        only(texts, "time (s from start)");
        for (Drawn d : texts) {
            assertFalse(d.text().matches("[0-9,.]{7,}"), "epoch-sized tick " + d.text());
        }
        assertTrue(texts.stream().anyMatch(d -> d.text().equals("0")), "the axis starts at the run's start: " + texts);
    }

    @Test
    void aLogCountedInTicksSaysSoAndHasWholeTicks() {
        Timeline t = new Timeline(100, new double[] {100, 101, 102, 103, 104, 105}, new double[] {60, 50, 40, 30, 20, 10},
                Clock.TICKS);
        JFreeChart chart = ReportCharts.battery(run(102.0, 104.0), t, RULE);
        List<Drawn> texts = texts(chart, 560, 260);
        only(texts, "time (ticks from start)");
        assertTrue(chart.getTitle().getText().endsWith("lead 2 ticks"), chart.getTitle().getText());
        double[] ticks = texts.stream().filter(d -> d.top() > 200 && d.text().matches("[0-9.]+"))
                .mapToDouble(d -> Double.parseDouble(d.text())).toArray();
        assertTrue(ticks.length >= 2, texts.toString());
        for (double x : ticks) {
            assertEquals(Math.rint(x), x, "tick " + x);
        }
    }

    @Test
    void warningAndViolationLabelsNeverOverlapHoweverShortTheLead() {
        Timeline t = new Timeline(0, new double[] {0, 10, 20, 30, 40}, new double[] {90, 70, 40, 19, 5},
                Clock.SECONDS);
        for (double[] wv : new double[][] {{29.9, 30}, {29.99, 30}, {30, 30}, {30.5, 30}, {39.9, 40}, {1, 1.05}}) {
            List<Drawn> texts = texts(ReportCharts.battery(run(wv[0], wv[1]), t, RULE), 560, 260);
            Drawn w = only(texts, "warning");
            Drawn v = only(texts, "violation");
            assertFalse(w.overlaps(v), w + " and " + v);
            for (Drawn d : List.of(w, v)) {
                assertTrue(d.x() >= 0 && d.x() + d.w() <= 560, d + " inside the chart");
            }
        }
    }

    @Test
    void theLeadHistogramIsFlatWithWholeRunsAndRoundBins() {
        JFreeChart chart = ReportCharts.leads(new double[] {3.4, 3.9, 3.8, 5.1, 8.7, 8.5, 12.2, 11.9, 17.0, 19.0},
                Clock.SECONDS);
        String svg = svg(chart);
        assertFalse(svg.contains("Gradient"), "no gradient bars");
        assertTrue(svg.contains("fill: rgb(31,84,158)") || svg.contains("fill:rgb(31,84,158)"), "flat bars");
        assertFalse(svg.contains("rgb(192,192,192)"), "no grey plot background");
        for (Drawn d : texts(chart, 700, 320)) {
            if (d.x() < 60 && d.text().matches("[0-9.]+")) {
                assertEquals(Math.rint(Double.parseDouble(d.text())), Double.parseDouble(d.text()), "run count " + d);
            }
        }
    }

    @Test
    void binsAreRoundAndAtMostTwenty() {
        assertEquals(1, ReportCharts.binWidth(15.6));
        assertEquals(1, ReportCharts.binWidth(20));
        assertEquals(2, ReportCharts.binWidth(21));
        assertEquals(0.5, ReportCharts.binWidth(7), 1e-12);
        assertEquals(50, ReportCharts.binWidth(900));
        assertEquals(1, ReportCharts.binWidth(0));
    }
}
