package dev.predmon.report;

import java.awt.Font;
import java.awt.font.FontRenderContext;
import java.util.Locale;

/**
 * What every drawing of the report shares: the font its texts are measured in, numbers written short, and text
 * escaped for HTML and SVG alike. Styles are not here but in the page's one style sheet ({@code report.css}), so
 * that a drawing names a class instead of repeating colours and strokes on every element.
 */
final class Svg {

    /** The font of every text in the drawings, as the style sheet sets it: 11 px sans-serif. */
    static final Font FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 11);
    private static final Font BOLD = FONT.deriveFont(Font.BOLD);
    private static final FontRenderContext FRC = new FontRenderContext(null, true, true);

    private Svg() {
    }

    /** Width of {@code text} in {@link #FONT}, bold or not. */
    static double width(String text, boolean bold) {
        return (bold ? BOLD : FONT).getStringBounds(text, FRC).getWidth();
    }

    /** A coordinate with one decimal at most: {@code 12.5}, {@code 40}. */
    static String num(double d) {
        long tenths = Math.round(d * 10);
        return tenths % 10 == 0 ? Long.toString(tenths / 10) : String.format(Locale.ROOT, "%.1f", tenths / 10.0);
    }

    /** {@code s} safe in HTML text, attribute values and SVG. */
    static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }

    /** A {@code <text>} of class {@code cls} at {@code x, y}. */
    static String text(String cls, double x, double y, String text) {
        return "<text class=\"" + cls + "\" x=\"" + num(x) + "\" y=\"" + num(y) + "\">" + esc(text) + "</text>";
    }
}
