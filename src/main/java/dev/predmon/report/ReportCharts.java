package dev.predmon.report;

import dev.predmon.abstraction.SafetyRule;
import dev.predmon.evaluate.RunResult;
import dev.predmon.parse.Clock;
import org.jfree.chart.ChartFactory;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.IntervalMarker;
import org.jfree.chart.plot.PlotOrientation;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYBarRenderer;
import org.jfree.chart.ui.RectangleAnchor;
import org.jfree.chart.ui.RectangleInsets;
import org.jfree.chart.ui.TextAnchor;
import org.jfree.data.statistics.HistogramDataset;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * The report's charts, in {@link ChartStyle}: a run's watched value over time with its warning and violation,
 * and the distribution of leads.
 */
final class ReportCharts {

    /** Height of one row of marker labels: the warning's label is in the first row, the violation's in the second. */
    private static final double LABEL_ROW = 15;
    private static final Font LABEL_FONT = new Font(Font.SANS_SERIF, Font.BOLD, 10);
    private static final int MAX_BINS = 20;
    private static final int MIN_BINS = 8;

    private ReportCharts() {
    }

    /**
     * The watched value of run {@code r} over time since the start of its log, the bound dashed, the warning
     * (dashed) and the violation (solid) as vertical lines, the lead between them shaded. The two lines' labels
     * are in rows of their own, so they never overlap however short the lead, and each is written on the side of
     * its line that has room.
     */
    static JFreeChart battery(RunResult r, Timeline t, SafetyRule rule) {
        XYSeries s = new XYSeries(rule.command());
        for (int i = 0; i < t.times().length; i++) {
            s.add(t.sinceStart(t.times()[i]), t.values()[i]);
        }
        String title = r.scenario() + " / " + Path.of(r.log()).getFileName() + ": " + r.verdict().id()
                + (r.lead() != null ? ", lead " + Timeline.amount(t.clock(), r.lead()) : "");
        JFreeChart chart = ChartFactory.createXYLineChart(title, Timeline.axisLabel(t.clock()), rule.command(),
                new XYSeriesCollection(s), PlotOrientation.VERTICAL, false, false, false);
        ChartStyle.apply(chart);
        chart.getTitle().setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
        XYPlot plot = chart.getXYPlot();
        NumberAxis x = (NumberAxis) plot.getDomainAxis();
        x.setAutoRangeIncludesZero(true);
        if (t.clock() == Clock.TICKS) {
            x.setStandardTickUnits(NumberAxis.createIntegerTickUnits());
        }
        plot.getRenderer().setSeriesStroke(0, new BasicStroke(1.6f));
        plot.addRangeMarker(new ValueMarker(rule.below(), Color.GRAY, new BasicStroke(1f, BasicStroke.CAP_BUTT,
                BasicStroke.JOIN_MITER, 10f, new float[] {4f, 3f}, 0f)));
        double end = Math.max(t.times().length == 0 ? 0 : t.sinceStart(t.times()[t.times().length - 1]), 1e-9);
        Double warning = r.warningTime() == null ? null : t.sinceStart(r.warningTime());
        Double violation = r.violationTime() == null ? null : t.sinceStart(r.violationTime());
        if (warning != null && violation != null && warning < violation) {
            IntervalMarker lead = new IntervalMarker(warning, violation);
            lead.setPaint(new Color(ChartStyle.WARNING.getRed(), ChartStyle.WARNING.getGreen(),
                    ChartStyle.WARNING.getBlue(), 28));
            lead.setOutlinePaint(null);
            plot.addDomainMarker(lead);
        }
        if (warning != null) {
            plot.addDomainMarker(marker(warning, end, ChartStyle.WARNING, "warning", 0, true));
        }
        if (violation != null) {
            plot.addDomainMarker(marker(violation, end, ChartStyle.VIOLATION, "violation", 1, false));
        }
        return chart;
    }

    /** A vertical line at {@code x} labelled in label row {@code row}, on its right unless near the end. */
    private static ValueMarker marker(double x, double end, Color color, String label, int row, boolean dashed) {
        ValueMarker m = new ValueMarker(x, color, dashed
                ? new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {6f, 3f}, 0f)
                : new BasicStroke(2f));
        m.setLabel(label);
        m.setLabelFont(LABEL_FONT);
        m.setLabelPaint(color);
        m.setLabelBackgroundColor(new Color(255, 255, 255, 230));
        m.setLabelOffset(new RectangleInsets(4 + row * LABEL_ROW, 4, 0, 4));
        boolean right = x / end < 0.85;
        m.setLabelAnchor(right ? RectangleAnchor.TOP_RIGHT : RectangleAnchor.TOP_LEFT);
        m.setLabelTextAnchor(right ? TextAnchor.TOP_LEFT : TextAnchor.TOP_RIGHT);
        return m;
    }

    /**
     * A histogram of {@code leads}: bins of a round width (1, 2 or 5 times a power of ten) starting at a multiple
     * of it, at most {@value #MAX_BINS}, whole numbers of runs on the vertical axis.
     */
    static JFreeChart leads(double[] leads, Clock clock) {
        double min = Arrays.stream(leads).min().orElse(0);
        double max = Arrays.stream(leads).max().orElse(0);
        double width = binWidth(max - min);
        double from = Math.floor(min / width) * width;
        int bins = Math.max(1, (int) Math.ceil((max - from) / width - 1e-9));
        if (from + bins * width <= max) {
            bins++; // max on a bin's edge: the last bin is [edge, edge + width)
        }
        HistogramDataset d = new HistogramDataset();
        d.addSeries("lead", leads, bins, from, from + bins * width);
        String unit = clock.unit();
        JFreeChart chart = ChartFactory.createHistogram("Lead of the warning over the violation (" + leads.length
                + (leads.length == 1 ? " hit)" : " hits)"), "lead (" + unit + ")", "runs", d, PlotOrientation.VERTICAL, false, false, false);
        ChartStyle.apply(chart);
        XYPlot plot = chart.getXYPlot();
        plot.getRangeAxis().setStandardTickUnits(NumberAxis.createIntegerTickUnits());
        // At least MIN_BINS bins wide, the bars centred, so that a single lead is a bar, not the whole plot.
        int pad = Math.max(0, MIN_BINS - bins);
        double lower = Math.max(Math.min(0, from), from - (pad / 2) * width);
        plot.getDomainAxis().setRange(lower, lower + Math.max(MIN_BINS, bins + (from - lower) / width) * width);
        XYBarRenderer bars = (XYBarRenderer) plot.getRenderer();
        bars.setSeriesPaint(0, ChartStyle.DATA);
        bars.setDrawBarOutline(true);
        bars.setSeriesOutlinePaint(0, Color.WHITE);
        bars.setSeriesOutlineStroke(0, new BasicStroke(1f));
        return chart;
    }

    /** The smallest of 1, 2, 5, 10, 20, ... (or 0.5, 0.2, ...) that cuts {@code range} into at most MAX_BINS. */
    static double binWidth(double range) {
        if (!(range > 0)) {
            return 1;
        }
        double w = Math.pow(10, Math.floor(Math.log10(range / MAX_BINS)));
        for (double f : new double[] {1, 2, 5, 10}) {
            if (range / (w * f) <= MAX_BINS) {
                return w * f;
            }
        }
        return w * 10;
    }
}
