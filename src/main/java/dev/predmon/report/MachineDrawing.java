package dev.predmon.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * Draws a learned Mealy machine as inline SVG, laid out by {@link MachineLayout} (ELK's layered algorithm):
 * states as circles, the initial one marked by an arrow from nowhere, edges as splines with an arrowhead,
 * every transition's {@code input / output} written once beside its edge, and a state's self-loops of more
 * than one transition counted on one line (the report lists them). No Graphviz needed, and the same machine
 * always gives the same picture.
 *
 * <p>The drawing names classes of the page's style sheet instead of repeating colours, and its arrowhead is the
 * page's one {@code <marker id="arrow">} ({@link #DEFS}), so a machine costs its geometry and its text only.
 * It is drawn at its natural size, one unit a CSS pixel, scaled down to the width of its box when it is wider
 * (the report offers it at full size too, see {@link ModelSection}). Every
 * text element carries its measured width as {@code textLength}, so a browser whose sans-serif font is wider
 * than the one measured squeezes the text into the box the layout kept free for it rather than across a
 * neighbour. Labels have a white halo, so that where an edge passes under one the text still reads.
 */
public final class MachineDrawing {

    /** The definitions every drawing refers to, written once per page: the arrowhead of every edge. */
    static final String DEFS = "<marker id=\"arrow\" viewBox=\"0 0 10 8\" refX=\"10\" refY=\"4\" "
            + "markerUnits=\"userSpaceOnUse\" markerWidth=\"11\" markerHeight=\"9\" orient=\"auto\">"
            + "<path d=\"M0,0L10,4L0,8z\"/></marker>";

    private MachineDrawing() {
    }

    /** {@code g} drawn as an {@code <svg>} element. */
    public static String svg(MachineGraph g) {
        return svg(MachineLayout.of(g));
    }

    /** {@code layout} drawn as an {@code <svg>} element. */
    public static String svg(MachineLayout layout) {
        StringBuilder s = new StringBuilder(8192);
        double w = Math.ceil(layout.width());
        double h = Math.ceil(layout.height());
        s.append("<svg class=\"mealy\" width=\"").append(Svg.num(w)).append("\" height=\"").append(Svg.num(h))
                .append("\" viewBox=\"0 0 ").append(Svg.num(w)).append(' ').append(Svg.num(h)).append("\">\n");
        for (MachineLayout.Line e : layout.edges()) {
            List<double[]> p = clipped(layout, e);
            s.append("<path class=\"e\" d=\"");
            for (int i = 0; i < p.size(); i++) {
                s.append(i == 0 ? "M" : !e.curve() ? "L" : i % 3 == 1 ? "C" : " ")
                        .append(num(p.get(i)[0])).append(',').append(num(p.get(i)[1]));
            }
            s.append("\"/>\n");
        }
        // Circles after the edges, texts after the circles: a text is never hidden.
        for (MachineLayout.State st : layout.states()) {
            MachineLayout.Box b = st.box();
            s.append("<circle class=\"").append(st.initial() ? "s0" : "s").append("\" cx=\"")
                    .append(num(b.x() + b.w() / 2)).append("\" cy=\"").append(num(b.y() + b.h() / 2))
                    .append("\" r=\"").append(num(b.w() / 2)).append("\"/>\n");
        }
        // State names plain (inside their circle), labels with a white halo (class l).
        for (MachineLayout.Text t : layout.texts()) {
            s.append("<text").append(t.label() ? " class=\"l\"" : "").append(" x=\"").append(num(t.box().x()))
                    .append("\" y=\"").append(num(t.baseline())).append("\" textLength=\"").append(num(t.box().w()))
                    .append("\" lengthAdjust=\"spacingAndGlyphs\">").append(Svg.esc(t.text())).append("</text>\n");
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
}
