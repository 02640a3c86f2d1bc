package dev.predmon.matching;

import dev.predmon.mealy.MealyMapping;
import dev.predmon.mealy.MealySteps;
import dev.predmon.model.LearnedModel;
import net.automatalib.automaton.CompactTransition;
import net.automatalib.automaton.transducer.CompactMealy;

/**
 * Runs one model along a trace, one Mealy step at a time, keeping only its current state, its discrepancy
 * count and whether it is still alive: constant work per step, constant memory.
 *
 * <p>It walks with {@code getSuccessor}/{@code getOutput} rather than AutomataLib's {@code computeOutput},
 * which silently truncates its answer at an undefined transition. The two negative cases of the thesis
 * (Section 5.1.1) stay apart: an output that differs is a <em>discrepancy</em> (the walk goes on, following
 * the input); an input the model has no transition for ends the walk (the thesis's "Key exception").
 */
public final class ModelTracker implements MealySteps<ModelTracker.Outcome> {

    /** What one step did. */
    public enum Outcome { MATCH, DISCREPANCY, UNDEFINED }

    /**
     * Why a model stopped matching.
     *
     * @param step     0-based Mealy step
     * @param input    the input at that step
     * @param expected the model's output there, or null when the input was undefined
     * @param seen     the observed output
     */
    public record Failure(int step, String input, String expected, String seen) {

        /** One line for users. */
        public String describe() {
            return expected == null
                    ? "cannot take input " + input + " at step " + step
                    : "after " + input + " at step " + step + " expected " + expected + " but saw " + seen;
        }
    }

    private final LearnedModel model;
    private final int tolerance;
    private int state;
    private int steps;
    private int discrepancies;
    private Failure firstDiscrepancy;
    private Failure elimination;

    /** @param tolerance discrepancies tolerated; one more eliminates the model (0: exact matching) */
    public ModelTracker(LearnedModel model, int tolerance) {
        this.model = model;
        this.tolerance = tolerance;
        reset();
    }

    /** Back to the initial state, alive, no discrepancy. */
    public void reset() {
        state = model.machine().getIntInitialState();
        steps = 0;
        discrepancies = 0;
        firstDiscrepancy = null;
        elimination = null;
    }

    /** Feeds one Mealy step; a model already eliminated stays so and answers {@link Outcome#UNDEFINED}. */
    @Override
    public Outcome step(String input, String observed) {
        if (elimination != null) {
            return Outcome.UNDEFINED;
        }
        int at = steps++;
        CompactMealy<String, String> m = model.machine();
        CompactTransition<String> t = model.alphabet().containsSymbol(input) ? m.getTransition(state, input) : null;
        if (t == null) {
            elimination = new Failure(at, input, null, observed);
            return Outcome.UNDEFINED;
        }
        String expected = m.getTransitionOutput(t);
        state = m.getIntSuccessor(t);
        if (observed.equals(expected)) {
            return Outcome.MATCH;
        }
        discrepancies++;
        Failure f = new Failure(at, input, expected, observed);
        if (firstDiscrepancy == null) {
            firstDiscrepancy = f;
        }
        if (discrepancies > tolerance) {
            elimination = f;
        }
        return Outcome.DISCREPANCY;
    }

    /**
     * Feeds one query/reply pair as its two Mealy steps, {@code input/OK} then {@code Delta/output} (the thesis's
     * I/O-automaton-to-Mealy mapping); returns whether the model is still alive.
     */
    public boolean pair(String input, String output) {
        MealyMapping.feedPair(this, input, output);
        return alive();
    }

    public LearnedModel model() {
        return model;
    }

    public boolean alive() {
        return elimination == null;
    }

    public int discrepancies() {
        return discrepancies;
    }

    public int steps() {
        return steps;
    }

    /** The step that eliminated the model, or null while it is alive. */
    public Failure elimination() {
        return elimination;
    }

    /** The first output that differed, or null. */
    public Failure firstDiscrepancy() {
        return firstDiscrepancy;
    }
}
