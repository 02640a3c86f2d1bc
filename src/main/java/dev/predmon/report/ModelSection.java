package dev.predmon.report;

import dev.predmon.evaluate.Evaluation;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelStore;

/**
 * The report's section of learned models: each machine drawn with its waiting states folded
 * ({@link MachineGraph#folded}), the states' self-loops of more than one transition listed under the drawing, and,
 * behind a click, every state drawn and the DOT text.
 */
final class ModelSection {

    private ModelSection() {
    }

    static void html(StringBuilder h, Evaluation e) {
        h.append("<h2 id=models>Learned models</h2>\n<p>")
                .append(e.mode().equals("cross-validation")
                        ? "Learned on every training log (each fold's models are learned on a subset of these runs)."
                        : "Learned on the training logs.")
                .append(" Laid out with ELK's layered algorithm; the initial state is the filled circle with an arrow "
                        + "from nowhere, and every arrowhead points to the state a transition leads to. Labels "
                        + "<code>input</code> (answered OK) and <code>input / output</code>. A state that many "
                        + "transitions leave unchanged carries one label that counts them; they are listed under the "
                        + "drawing. A machine wider than the page is scaled to fit it; tick its \"full size\" box to read it "
                        + "at its natural size and scroll it sideways.</p>\n");
        if (e.models() == null) {
            return;
        }
        int n = 0;
        for (LearnedModel m : e.models().models()) {
            MachineGraph folded = MachineGraph.folded(m);
            h.append("<h3>").append(Svg.esc(m.id())).append(" (").append(m.faulty() ? "faulty" : "nominal")
                    .append(", ").append(m.machine().size()).append(" states)</h3>\n<p class=caption>")
                    .append(caption(folded)).append("</p>\n");
            drawing(h, MachineLayout.of(folded), "z" + n++);
            selfLoops(h, folded);
            if (folded.hidden() > 0) {
                MachineGraph full = MachineGraph.full(m);
                h.append("<details><summary>every state (").append(full.nodes().size()).append(" states, ")
                        .append(full.edges().stream().mapToInt(x -> x.labels().size()).sum())
                        .append(" transitions)</summary>\n");
                drawing(h, MachineLayout.of(full), "z" + n++);
                selfLoops(h, full);
                h.append("</details>\n");
            }
            h.append("<details><summary>DOT</summary><pre>")
                    .append(Svg.esc(ModelStore.toDot(m.machine(), m.alphabet()))).append("</pre></details>\n");
        }
    }

    /**
     * A drawing in its box. One wider than the page is scaled down to fit, which shows the whole machine at once;
     * a "full size" box (a checkbox and the style sheet, no script) shows it at its natural size, to be scrolled.
     */
    private static void drawing(StringBuilder h, MachineLayout layout, String id) {
        if (layout.width() > MachineLayout.PAGE_WIDTH) {
            h.append("<input type=checkbox class=zoom id=").append(id).append("><label for=").append(id)
                    .append(">full size (scaled to ").append(Math.round(100 * MachineLayout.PAGE_WIDTH / layout.width()))
                    .append("% to fit the page)</label>\n");
        }
        h.append("<div class=machine>").append(MachineDrawing.svg(layout)).append("</div>\n");
    }

    /** The transitions of every counted self-loop of {@code g}, one line per state. */
    private static void selfLoops(StringBuilder h, MachineGraph g) {
        if (g.edges().stream().noneMatch(MachineGraph.Edge::counted)) {
            return;
        }
        h.append("<dl class=loops>");
        for (MachineGraph.Edge e : g.edges()) {
            if (e.counted()) {
                h.append("<dt>s").append(e.source()).append(", ").append(e.labels().size()).append(" self-loops</dt><dd>")
                        .append(Svg.esc(String.join(", ", e.labels()))).append("</dd>");
            }
        }
        h.append("</dl>\n");
    }

    /** What the drawing of {@code g} shows of its machine: every state, or which were folded and how. */
    static String caption(MachineGraph g) {
        if (g.hidden() == 0) {
            return "All " + g.states() + " states drawn, one arrow per pair of states.";
        }
        return g.states() + " states, " + g.nodes().size() + " drawn: the other " + g.hidden() + " only wait for the "
                + "reply to a query (<code>input / OK</code> then <code>Delta / reply</code>), so each such pair is "
                + "drawn as one arrow <code>input / reply</code>. Every state is drawn below, and in the DOT text.";
    }
}
