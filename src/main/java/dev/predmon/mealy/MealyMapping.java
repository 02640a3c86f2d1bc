package dev.predmon.mealy;

import dev.predmon.compact.IoPair;
import net.automatalib.automaton.CompactTransition;
import net.automatalib.automaton.transducer.CompactMealy;
import net.automatalib.word.Word;
import net.automatalib.word.WordBuilder;

import java.util.List;

/**
 * The I/O-automaton to Mealy mapping of the thesis (Section 2.3.2, Figure 4.9): every input symbol of the
 * interface is a Mealy input answered {@value #OK}, and every output symbol is the answer to the dummy input
 * {@value #DELTA}. A query/reply pair {@code (i, o)} is thus the two steps {@code i/OK, Delta/o}.
 */
public final class MealyMapping {

    /** The dummy input whose answer is the component's reply. */
    public static final String DELTA = "Delta";
    /** The dummy output that answers every real input. */
    public static final String OK = "OK";

    private MealyMapping() {
    }

    /**
     * The state {@code machine} reaches from {@code state} on the pair {@code (input, output)}, as its two steps
     * {@code input/OK} and {@code Delta/output}; -1 when it cannot take the input or answers otherwise.
     */
    public static int pairStep(CompactMealy<String, String> machine, int state, String input, String output) {
        if (!machine.getInputAlphabet().containsSymbol(input)) {
            return -1;
        }
        // one transition object per step, read for both successor and output (each lookup makes one)
        CompactTransition<String> step = machine.getTransition(state, input);
        if (step == null || !OK.equals(machine.getTransitionOutput(step))) {
            return -1;
        }
        CompactTransition<String> answer = machine.getTransition(machine.getIntSuccessor(step), DELTA);
        if (answer == null || !output.equals(machine.getTransitionOutput(answer))) {
            return -1;
        }
        return machine.getIntSuccessor(answer);
    }

    /**
     * Feeds the pair {@code (input, output)} to {@code steps} as its two Mealy steps, {@code input/OK} then
     * {@code Delta/output}; returns what the second step answered.
     */
    public static <R> R feedPair(MealySteps<R> steps, String input, String output) {
        steps.step(input, OK);
        return steps.step(DELTA, output);
    }

    /** The index of the pair whose command or reply is Mealy step {@code step} (0-based; two steps per pair). */
    public static int pairOfStep(int step) {
        return step / 2;
    }

    /** Whether Mealy step {@code step} is a pair's command ({@code input/OK}) rather than its reply ({@code Delta/output}). */
    public static boolean isCommandStep(int step) {
        return step % 2 == 0;
    }

    /** Maps a compacted trace to its Mealy sample. */
    public static MealyTrace toTrace(List<IoPair> pairs, String source) {
        WordBuilder<String> in = new WordBuilder<>(pairs.size() * 2);
        WordBuilder<String> out = new WordBuilder<>(pairs.size() * 2);
        for (IoPair p : pairs) {
            in.append(p.input()).append(DELTA);
            out.append(OK).append(p.output());
        }
        Word<String> inputs = in.toWord();
        return new MealyTrace(inputs, out.toWord(), source);
    }
}
