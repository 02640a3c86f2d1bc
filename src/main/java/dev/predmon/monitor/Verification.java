package dev.predmon.monitor;

import dev.predmon.matching.ModelTracker;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.LearnedModel;

/**
 * Algorithm 6 of the thesis with its three cases (Section 5.1.1): the model reproduces the trace's outputs;
 * it takes every input but some outputs differ; or some input cannot be taken.
 *
 * @param verdict       the case
 * @param steps         Mealy steps walked
 * @param discrepancies outputs that differed
 * @param failure       the first difference (case 2) or the input that could not be taken (case 3), else null
 */
public record Verification(Verdict verdict, int steps, int discrepancies, ModelTracker.Failure failure) {

    /** The thesis's three cases. */
    public enum Verdict { MATCHES, OUTPUTS_DIFFER, INPUT_UNDEFINED }

    /** Runs {@code trace} through {@code model} to its end or to the first input it cannot take. */
    public static Verification of(LearnedModel model, MealyTrace trace) {
        ModelTracker t = new ModelTracker(model, Integer.MAX_VALUE);
        for (int i = 0; i < trace.length() && t.alive(); i++) {
            t.step(trace.inputs().getSymbol(i), trace.outputs().getSymbol(i));
        }
        if (!t.alive()) {
            return new Verification(Verdict.INPUT_UNDEFINED, t.steps(), t.discrepancies(), t.elimination());
        }
        if (t.discrepancies() > 0) {
            return new Verification(Verdict.OUTPUTS_DIFFER, t.steps(), t.discrepancies(), t.firstDiscrepancy());
        }
        return new Verification(Verdict.MATCHES, t.steps(), 0, null);
    }
}
