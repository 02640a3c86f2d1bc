package dev.predmon.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * Draws a learned Mealy machine as inline SVG, laid out by {@link MachineLayout} (ELK's layered algorithm):
 * states as circles, the initial one marked by an arrow from nowhere, edges as splines with an arrow head,
 * every transition's {@code input / output} written once beside its edge. No Graphviz needed, and the same
 * machine always gives the same picture.
 *
 * <p>The SVG is drawn at its natural size, one unit a CSS pixel, so its text stays readable however large the
 * machine: the page scrolls it instead of shrinking it. Every text element carries its measured width as
 * {@code textLength}, so a browser whose sans-serif font is wider than the one measured squeezes the text into
 * the box the layout kept free for it rather than across a neighbour. Labels have a white halo, so that where
 * an edge passes under one (the fan of a state's many edges can) the text still reads.
 */
public final class MachineDrawing {

    private static final String EDGE = "#555";
    private static final String LABEL = "#1a3f7a";

    private MachineDrawing() {
    }

    /** {@code g} drawn as an {@code <svg>} element; {@code key} keeps element ids unique within a page. */
    public static String svg(MachineGraph g, String key) {
        return svg(MachineLayout.of(g), key);
    }

    /** {@code layout} drawn as an {@code <svg>} element; {@code key} keeps element ids unique within a page. */
    public static String svg(MachineLayout layout, String key) {
        StringBuilder s = new StringBuilder(8192);
        String arrow = key + "arrow";
        s.append(String.format(Locale.ROOT, "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"mealy\" "
                        + "width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" "
                        + "font-size=\"%d\">\n", Math.ceil(layout.width()), Math.ceil(layout.height()),
                Math.ceil(layout.width()), Math.ceil(layout.height()), MachineLayout.FONT.getSize()));
        s.append("<defs><marker id=\"").append(arrow).append("\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" "
                + "markerWidth=\"7\" markerHeight=\"7\" orient=\"auto\"><path d=\"M0,0L10,5L0,10z\" fill=\"")
                .append(EDGE).append("\"/></marker></defs>\n");
        s.append("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<g fill=\"none\" stroke=\"").append(EDGE)
                .append("\" stroke-width=\"1.2\">\n");
        for (MachineLayout.Line e : layout.edges()) {
            List<double[]> p = clipped(layout, e);
            s.append("<path d=\"");
            for (int i = 0; i < p.size(); i++) {
                s.append(i == 0 ? "M" : !e.curve() ? "L" : i % 3 == 1 ? "C" : " ")
                        .append(num(p.get(i)[0])).append(',').append(num(p.get(i)[1]));
            }
            s.append("\" marker-end=\"url(#").append(arrow).append(")\"/>\n");
        }
        s.append("</g>\n");
        // Circles after the edges, texts after the circles: a text is never hidden.
        for (MachineLayout.State st : layout.states()) {
            MachineLayout.Box b = st.box();
            s.append("<circle cx=\"").append(num(b.x() + b.w() / 2)).append("\" cy=\"").append(num(b.y() + b.h() / 2))
                    .append("\" r=\"").append(num(b.w() / 2)).append(st.initial()
                            ? "\" fill=\"#dce8fb\" stroke=\"#000\" stroke-width=\"2\"/>\n"
                            : "\" fill=\"#f4f4f4\" stroke=\"#000\" stroke-width=\"1\"/>\n");
        }
        // State names plain (inside their circle), labels with a white halo.
        for (boolean label : new boolean[] {false, true}) {
            s.append(label ? "<g fill=\"" + LABEL + "\" stroke=\"white\" stroke-width=\"3\" stroke-linejoin=\"round\" "
                    + "paint-order=\"stroke\">\n" : "<g>\n");
            for (MachineLayout.Text t : layout.texts()) {
                if (t.label() == label) {
                    s.append("<text x=\"").append(num(t.box().x())).append("\" y=\"").append(num(t.baseline()))
                            .append("\" textLength=\"").append(num(t.box().w()))
                            .append("\" lengthAdjust=\"spacingAndGlyphs\">").append(esc(t.text())).append("</text>\n");
                }
            }
            s.append("</g>\n");
        }
        return s.append("</svg>").toString();
    }

    /**
     * The edge's points with both ends moved from the state's bounding box onto its circle, along the end
     * segment (ELK routes to the box; the gap would show between a circle and its arrow).
     */
    private static List<double[]> clipped(MachineLayout layout, MachineLayout.Line e) {
        List<double[]> p = new ArrayList<>(e.points());
        if (p.size() < 2) {
            return p;
        }
        stateOf(layout, e.source()).ifPresent(b -> p.set(0, ontoCircle(p.get(0), p.get(1), b)));
        int n = p.size();
        stateOf(layout, e.target()).ifPresent(b -> p.set(n - 1, ontoCircle(p.get(n - 1), p.get(n - 2), b)));
        return p;
    }

    private static Optional<MachineLayout.Box> stateOf(MachineLayout layout, int id) {
        return layout.states().stream().filter(s -> s.id() == id).map(MachineLayout.State::box).findFirst();
    }

    /**
     * Moves {@code end} along the direction from {@code prev} to it until it meets the circle inscribed in
     * {@code b}; unchanged when that line misses the circle.
     */
    private static double[] ontoCircle(double[] end, double[] prev, MachineLayout.Box b) {
        double cx = b.x() + b.w() / 2;
        double cy = b.y() + b.h() / 2;
        double r = b.w() / 2;
        double dx = end[0] - prev[0];
        double dy = end[1] - prev[1];
        double len = Math.hypot(dx, dy);
        if (len == 0) {
            return end;
        }
        dx /= len;
        dy /= len;
        // |end + t*d - c| = r, for the smallest t: t^2 + 2t(d.(end-c)) + |end-c|^2 - r^2 = 0.
        double ox = end[0] - cx;
        double oy = end[1] - cy;
        double bq = dx * ox + dy * oy;
        double disc = bq * bq - (ox * ox + oy * oy - r * r);
        if (disc < 0) {
            return end;
        }
        double t = -bq - Math.sqrt(disc);
        return new double[] {end[0] + t * dx, end[1] + t * dy};
    }

    private static String num(double d) {
        return String.format(Locale.ROOT, "%.1f", d);
    }

    private static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
