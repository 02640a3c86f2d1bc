package dev.predmon.report;

import org.jfree.chart.JFreeChart;
import org.jfree.chart.StandardChartTheme;
import org.jfree.chart.plot.DefaultDrawingSupplier;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.category.StandardBarPainter;
import org.jfree.chart.renderer.xy.StandardXYBarPainter;
import org.jfree.chart.ui.RectangleInsets;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Paint;

/**
 * The report's chart style: flat, white, dark text, thin solid grid lines, no gradients, no shadows, no grey
 * plot area, so that charts read on screen and in black-and-white print alike. Applied per chart through a
 * {@link StandardChartTheme} of its own; JFreeChart's global theme is left alone.
 */
final class ChartStyle {

    /** The battery curve and the histogram's bars. */
    static final Color DATA = new Color(31, 84, 158);
    /** The warning: orange, drawn dashed so that it differs from the violation in grey print too. */
    static final Color WARNING = new Color(214, 110, 0);
    /** The violation. */
    static final Color VIOLATION = new Color(190, 20, 20);
    /** Grid lines and the safety bound. */
    static final Color GRID = new Color(225, 225, 225);
    static final Color TEXT = new Color(34, 34, 34);

    private static final String FONT = Font.SANS_SERIF;

    private ChartStyle() {
    }

    /** Applies the style to {@code chart}: fonts, paints and flat bars; plots keep their own series colours. */
    static void apply(JFreeChart chart) {
        StandardChartTheme t = new StandardChartTheme("predmon flat", false);
        t.setExtraLargeFont(new Font(FONT, Font.BOLD, 14));
        t.setLargeFont(new Font(FONT, Font.BOLD, 12));
        t.setRegularFont(new Font(FONT, Font.PLAIN, 11));
        t.setSmallFont(new Font(FONT, Font.PLAIN, 10));
        t.setTitlePaint(TEXT);
        t.setSubtitlePaint(TEXT);
        t.setAxisLabelPaint(TEXT);
        t.setTickLabelPaint(TEXT);
        t.setChartBackgroundPaint(Color.WHITE);
        t.setPlotBackgroundPaint(Color.WHITE);
        t.setPlotOutlinePaint(new Color(160, 160, 160));
        t.setDomainGridlinePaint(GRID);
        t.setRangeGridlinePaint(GRID);
        t.setAxisOffset(new RectangleInsets(4, 4, 4, 4));
        t.setShadowVisible(false);
        t.setBarPainter(new StandardBarPainter());
        t.setXYBarPainter(new StandardXYBarPainter());
        t.setDrawingSupplier(new DefaultDrawingSupplier(new Paint[] {DATA}, new Paint[] {DATA},
                DefaultDrawingSupplier.DEFAULT_STROKE_SEQUENCE, DefaultDrawingSupplier.DEFAULT_OUTLINE_STROKE_SEQUENCE,
                DefaultDrawingSupplier.DEFAULT_SHAPE_SEQUENCE));
        t.apply(chart);
        if (chart.getPlot() instanceof XYPlot p) {
            // Solid, not JFreeChart's dashed grid: thin dashes turn to noise in print.
            p.setDomainGridlineStroke(new BasicStroke(0.8f));
            p.setRangeGridlineStroke(new BasicStroke(0.8f));
        }
    }
}
