package dev.predmon.report;

import dev.predmon.mealy.MealyMapping;
import dev.predmon.model.LearnedModel;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The graph a learned Mealy machine is drawn as: its states reachable from the initial one and one edge per
 * pair of states, labelled with every transition between them in alphabet order. Deterministic: the same
 * machine always gives the same graph.
 *
 * <p>The thesis's mapping turns each query/reply pair into two Mealy steps, {@code input/OK} into a state that
 * only waits for {@code Delta/reply}. {@link #folded} leaves such waiting states out and draws the pair as one
 * edge {@code input / reply} between the states that matter; it reads like the I/O automaton the machine stands
 * for and is a fraction of the size. {@link #full} draws every state and every transition as the DOT file has
 * them. Either way {@link #states} is the machine's size and {@link #hidden()} says how many states were left
 * out, so that a caption can say so.
 *
 * @param initial the initial state, -1 for a machine without one
 * @param states  states of the machine
 * @param nodes   states drawn, in breadth-first order from the initial state
 * @param edges   edges drawn, in the order of their source then first label
 * @param fold    whether waiting states were folded
 */
public record MachineGraph(int initial, int states, List<Integer> nodes, List<Edge> edges, boolean fold) {

    /**
     * An edge and its labels.
     *
     * @param source source state
     * @param target target state, equal to {@code source} for a self-loop
     * @param labels one {@code input / output} per transition ({@code input} alone when the output is OK)
     */
    public record Edge(int source, int target, List<String> labels) {

        /** Whether the edge is a self-loop of more than one transition, drawn with one line that counts them. */
        public boolean counted() {
            return source == target && labels.size() > 1;
        }

        /**
         * The lines written beside the edge: its transitions, or for a counted self-loop one line. A state that a
         * dozen inputs leave unchanged would otherwise carry a dozen stacked lines, taller than the rest of the
         * machine; the report lists them under the drawing instead.
         */
        public List<String> drawn() {
            return counted() ? List.of(labels.size() + " self-loops, listed below") : labels;
        }
    }

    /** The machine with waiting states folded into their query's edge. */
    public static MachineGraph folded(LearnedModel model) {
        return of(model, true);
    }

    /** The machine with every state and transition. */
    public static MachineGraph full(LearnedModel model) {
        return of(model, false);
    }

    /** States not drawn: folded ones, and any not reachable from the initial state. */
    public int hidden() {
        return states - nodes.size();
    }

    private static MachineGraph of(LearnedModel model, boolean fold) {
        CompactMealy<String, String> m = model.machine();
        Integer init = m.getInitialState();
        if (init == null) {
            return new MachineGraph(-1, m.size(), List.of(), List.of(), fold);
        }
        // Only symbols of the machine's own alphabet have transitions (as ModelTracker checks too).
        List<String> inputs = model.alphabet().stream().filter(m.getInputAlphabet()::containsSymbol).toList();
        Set<Integer> seen = new LinkedHashSet<>();
        Deque<Integer> queue = new ArrayDeque<>();
        seen.add(init);
        queue.add(init);
        Map<List<Integer>, List<String>> labels = new LinkedHashMap<>();
        while (!queue.isEmpty()) {
            Integer s = queue.poll();
            for (Step e : steps(m, inputs, s, fold)) {
                labels.computeIfAbsent(List.of(s, e.target()), k -> new ArrayList<>()).add(e.label());
                if (seen.add(e.target())) {
                    queue.add(e.target());
                }
            }
        }
        List<Edge> edges = new ArrayList<>();
        labels.forEach((k, v) -> edges.add(new Edge(k.get(0), k.get(1), List.copyOf(v))));
        return new MachineGraph(init, m.size(), List.copyOf(seen), List.copyOf(edges), fold);
    }

    /** One transition as drawn. */
    private record Step(Integer target, String label) {
    }

    /**
     * The transitions drawn from {@code s}: when folding, a query whose successor only waits for {@code Delta}
     * becomes one step {@code input / reply} to where the reply leads; any other transition is drawn as it is.
     */
    private static List<Step> steps(CompactMealy<String, String> m, List<String> inputs, Integer s, boolean fold) {
        List<Step> out = new ArrayList<>();
        for (String in : inputs) {
            // Boxed on purpose: the int overload of getSuccessor answers -1, not null, for a missing transition.
            Integer t = m.getSuccessor(s, in);
            if (t == null) {
                continue;
            }
            String answer = m.getOutput(s, in);
            if (fold && !in.equals(MealyMapping.DELTA) && MealyMapping.OK.equals(answer) && onlyWaits(m, inputs, t)) {
                out.add(new Step(m.getSuccessor(t, MealyMapping.DELTA), in + " / " + m.getOutput(t, MealyMapping.DELTA)));
            } else {
                out.add(new Step(t, MealyMapping.OK.equals(answer) ? in : in + " / " + answer));
            }
        }
        return out;
    }

    /** Whether {@code t}'s only transition is {@code Delta}: the state between a query and its reply. */
    private static boolean onlyWaits(CompactMealy<String, String> m, List<String> inputs, Integer t) {
        for (String in : inputs) {
            if (m.getSuccessor(t, in) != null && !in.equals(MealyMapping.DELTA)) {
                return false;
            }
        }
        return m.getSuccessor(t, MealyMapping.DELTA) != null;
    }
}
