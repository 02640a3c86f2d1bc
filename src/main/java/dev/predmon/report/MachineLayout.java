package dev.predmon.report;

import org.eclipse.elk.alg.layered.LayeredLayoutProvider;
import org.eclipse.elk.alg.layered.options.CycleBreakingStrategy;
import org.eclipse.elk.alg.layered.options.LayerConstraint;
import org.eclipse.elk.alg.layered.options.LayeredOptions;
import org.eclipse.elk.alg.layered.options.SplineRoutingMode;
import org.eclipse.elk.core.data.LayoutMetaDataService;
import org.eclipse.elk.core.math.ElkPadding;
import org.eclipse.elk.core.options.Direction;
import org.eclipse.elk.core.options.EdgeLabelPlacement;
import org.eclipse.elk.core.options.EdgeRouting;
import org.eclipse.elk.core.util.BasicProgressMonitor;
import org.eclipse.elk.graph.ElkBendPoint;
import org.eclipse.elk.graph.ElkEdge;
import org.eclipse.elk.graph.ElkEdgeSection;
import org.eclipse.elk.graph.ElkLabel;
import org.eclipse.elk.graph.ElkNode;
import org.eclipse.elk.graph.util.ElkGraphUtil;

import java.awt.Font;
import java.awt.font.FontRenderContext;
import java.awt.font.LineMetrics;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Where each state, edge and label of a {@link MachineGraph} goes, computed by Eclipse ELK's layered algorithm
 * (Sugiyama's method, as Graphviz's {@code dot}): states in layers from left to right, crossings minimised,
 * edges as splines. Each edge's labels form one block that ELK places as a node of its own between the layers,
 * so no label overlaps a state or another label; {@link #overlaps} checks that on the result.
 * Label sizes are measured with the font the drawing uses, so the boxes are the ones drawn.
 * Deterministic: ELK runs with a fixed random seed.
 *
 * @param width  width of the drawing
 * @param height height of the drawing
 * @param states the states, with their boxes
 * @param edges  the edges, from source border to target border, and last the initial state's arrow
 * @param texts  every line of text drawn (state names and edge labels), with its box
 */
public record MachineLayout(double width, double height, List<State> states, List<Line> edges, List<Text> texts) {

    /** The font of every text in the drawing. */
    public static final Font FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 11);
    /** Diameter of a state's circle. */
    public static final double STATE = 34;
    private static final FontRenderContext FRC = new FontRenderContext(null, true, true);
    private static final double PAD = 3;
    /** The width of the report's column for a drawing at its widest, in CSS pixels (the page's 1400 less margins). */
    static final double PAGE_WIDTH = 1330;

    static {
        // ELK's one-time set-up: the service's constructor registers how ELK copies option values (ElkReflect),
        // which the layered algorithm needs. Idempotent and thread-safe; nothing else of it is used.
        LayoutMetaDataService.getInstance();
    }

    /**
     * An axis-aligned box.
     *
     * @param x left
     * @param y top
     * @param w width
     * @param h height
     */
    public record Box(double x, double y, double w, double h) {

        /** Whether the interiors of this box and {@code o} intersect (touching edges do not count). */
        public boolean overlaps(Box o) {
            return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
        }
    }

    /**
     * A state.
     *
     * @param id      the machine's state number
     * @param initial whether it is the initial state
     * @param box     its circle's bounding box
     */
    public record State(int id, boolean initial, Box box) {
    }

    /**
     * An edge as a piecewise cubic Bézier curve, as ELK's spline routing gives it.
     *
     * @param source its source state, -1 for the arrow to the initial state
     * @param target its target state
     * @param points {x, y}: the start on the source's border, then per piece two control points and its end, the
     *               last on the target's border; if the count does not fit that ({@link #curve} false), a polyline
     */
    public record Line(int source, int target, List<double[]> points) {

        /** Whether {@link #points} are Bézier pieces (start plus three points per piece). */
        public boolean curve() {
            return points.size() >= 4 && (points.size() - 1) % 3 == 0;
        }
    }

    /**
     * One line of text.
     *
     * @param text     the text
     * @param box      the box it is drawn in: the text is {@code box.w()} wide
     * @param baseline y of its baseline
     * @param label    whether it is part of an edge label (else a state's name)
     */
    public record Text(String text, Box box, double baseline, boolean label) {
    }

    /**
     * The layout of {@code g}: layers from left to right, as the thesis draws its machines, unless that is wider
     * than {@link #PAGE_WIDTH} and layers from top to bottom fit it. A machine whose long labels sit between many
     * layers then grows down the page, which a reader scrolls anyway, instead of past its right edge.
     */
    public static MachineLayout of(MachineGraph g) {
        MachineLayout across = of(g, Direction.RIGHT);
        if (across.width() <= PAGE_WIDTH) {
            return across;
        }
        MachineLayout down = of(g, Direction.DOWN);
        return down.width() <= PAGE_WIDTH ? down : across;
    }

    private static MachineLayout of(MachineGraph g, Direction direction) {
        ElkNode root = ElkGraphUtil.createGraph();
        root.setProperty(LayeredOptions.DIRECTION, direction);
        root.setProperty(LayeredOptions.EDGE_ROUTING, EdgeRouting.SPLINES);
        // Conservative splines go around label blocks; ELK's default (sloppy) cut through a self-loop's labels.
        root.setProperty(LayeredOptions.EDGE_ROUTING_SPLINES_MODE, SplineRoutingMode.CONSERVATIVE);
        root.setProperty(LayeredOptions.RANDOM_SEED, 1);
        // Edges against the breadth-first order from the initial state are the ones turned back, so the machine
        // reads from its initial state on the left outwards, as in the thesis's figures. ELK's default (greedy)
        // put the initial state of the full 'depleted' machine in the middle, with the drawing half again as wide.
        root.setProperty(LayeredOptions.CYCLE_BREAKING_STRATEGY, CycleBreakingStrategy.MODEL_ORDER);
        root.setProperty(LayeredOptions.PADDING, new ElkPadding(12));
        root.setProperty(LayeredOptions.SPACING_NODE_NODE, 24.0);
        root.setProperty(LayeredOptions.SPACING_NODE_NODE_BETWEEN_LAYERS, 36.0);
        root.setProperty(LayeredOptions.SPACING_EDGE_LABEL, 4.0);
        root.setProperty(LayeredOptions.SPACING_LABEL_LABEL, 6.0);
        root.setProperty(LayeredOptions.SPACING_EDGE_EDGE, 12.0);
        root.setProperty(LayeredOptions.SPACING_EDGE_NODE, 12.0);
        root.setProperty(LayeredOptions.SPACING_NODE_SELF_LOOP, 12.0);
        // The initial state's arrow from nowhere: an edge from an invisible point in the first layer. Created
        // first, so that the breadth-first model order starts with it.
        ElkNode nowhere = g.initial() < 0 ? null : ElkGraphUtil.createNode(root);
        if (nowhere != null) {
            nowhere.setDimensions(1, 1);
            nowhere.setProperty(LayeredOptions.LAYERING_LAYER_CONSTRAINT, LayerConstraint.FIRST);
        }
        Map<Integer, ElkNode> nodes = new HashMap<>();
        for (int s : g.nodes()) {
            ElkNode n = ElkGraphUtil.createNode(root);
            n.setIdentifier("s" + s);
            n.setDimensions(STATE, STATE);
            nodes.put(s, n);
        }
        ElkEdge start = nowhere == null ? null : ElkGraphUtil.createSimpleEdge(nowhere, nodes.get(g.initial()));
        List<ElkEdge> edges = new ArrayList<>();
        for (MachineGraph.Edge e : g.edges()) {
            ElkEdge edge = ElkGraphUtil.createSimpleEdge(nodes.get(e.source()), nodes.get(e.target()));
            ElkLabel label = ElkGraphUtil.createLabel(String.join("\n", e.drawn()), edge);
            label.setDimensions(e.drawn().stream().mapToDouble(MachineLayout::width).max().orElse(0) + 2 * PAD,
                    e.drawn().size() * lineHeight());
            label.setProperty(LayeredOptions.EDGE_LABELS_PLACEMENT, EdgeLabelPlacement.CENTER);
            edges.add(edge);
        }
        new LayeredLayoutProvider().layout(root, new BasicProgressMonitor());

        List<State> states = new ArrayList<>();
        List<Text> texts = new ArrayList<>();
        for (int s : g.nodes()) {
            ElkNode n = nodes.get(s);
            Box box = new Box(n.getX(), n.getY(), n.getWidth(), n.getHeight());
            states.add(new State(s, s == g.initial(), box));
            texts.add(centred("s" + s, box.x() + box.w() / 2, box.y() + box.h() / 2, false));
        }
        List<Line> lines = new ArrayList<>();
        for (int i = 0; i < edges.size(); i++) {
            ElkEdge edge = edges.get(i);
            MachineGraph.Edge e = g.edges().get(i);
            lines.add(new Line(e.source(), e.target(), points(edge)));
            ElkLabel label = edge.getLabels().get(0);
            double y = label.getY();
            for (String text : e.drawn()) {
                texts.add(centred(text, label.getX() + label.getWidth() / 2, y + lineHeight() / 2, true));
                y += lineHeight();
            }
        }
        if (start != null) {
            lines.add(new Line(-1, g.initial(), points(start)));
        }
        // ELK sizes the graph by its nodes and edges; a self-loop's label can stick out past that, and would be cut off
        // at the edge of the drawing. The drawing is as large as everything drawn in it.
        double width = root.getWidth();
        double height = root.getHeight();
        for (Text t : texts) {
            width = Math.max(width, t.box().x() + t.box().w() + PAD);
            height = Math.max(height, t.box().y() + t.box().h() + PAD);
        }
        for (Line l : lines) {
            for (double[] p : l.points()) {
                width = Math.max(width, p[0] + PAD);
                height = Math.max(height, p[1] + PAD);
            }
        }
        return new MachineLayout(width, height, states, lines, texts);
    }

    /**
     * Every pair of texts whose boxes overlap, and every edge label over a state, as readable strings; empty
     * when every text can be read.
     */
    public List<String> overlaps() {
        List<String> found = new ArrayList<>();
        for (int i = 0; i < texts.size(); i++) {
            for (int j = i + 1; j < texts.size(); j++) {
                if (texts.get(i).box().overlaps(texts.get(j).box())) {
                    found.add("'" + texts.get(i).text() + "' overlaps '" + texts.get(j).text() + "'");
                }
            }
            for (State s : states) {
                if (texts.get(i).label() && texts.get(i).box().overlaps(s.box())) {
                    found.add("'" + texts.get(i).text() + "' overlaps state s" + s.id());
                }
            }
        }
        return found;
    }

    /** Width of {@code text} in {@link #FONT}. */
    public static double width(String text) {
        return FONT.getStringBounds(text, FRC).getWidth();
    }

    /**
     * Height of one line of a label in {@link #FONT}: the font's height plus 2 units, so that the lines of a
     * label block stay apart in a browser whose font metrics differ slightly from Java's.
     */
    public static double lineHeight() {
        LineMetrics m = FONT.getLineMetrics("Mg", FRC);
        return Math.ceil(m.getAscent() + m.getDescent() + m.getLeading()) + 2;
    }

    private static Text centred(String text, double cx, double cy, boolean label) {
        LineMetrics m = FONT.getLineMetrics(text, FRC);
        double w = width(text);
        double h = m.getAscent() + m.getDescent();
        return new Text(text, new Box(cx - w / 2, cy - h / 2, w, h), cy - h / 2 + m.getAscent(), label);
    }

    /** The edge's route: ELK gives one section from the source's border through its bends to the target's. */
    private static List<double[]> points(ElkEdge edge) {
        List<double[]> points = new ArrayList<>();
        for (ElkEdgeSection s : edge.getSections()) {
            points.add(new double[] {s.getStartX(), s.getStartY()});
            for (ElkBendPoint b : s.getBendPoints()) {
                points.add(new double[] {b.getX(), b.getY()});
            }
            points.add(new double[] {s.getEndX(), s.getEndY()});
        }
        return points;
    }
}
