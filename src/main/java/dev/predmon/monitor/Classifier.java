package dev.predmon.monitor;

import dev.predmon.matching.ModelTracker;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;

/**
 * Algorithm 7 of the thesis (MatchTraces), off-line: every model runs the whole trace; a model that cannot take
 * some input is deleted; the others get their discrepancy count; the best match is the model with the fewest
 * discrepancies within the threshold, except that a nominal model within the threshold is preferred to any faulty
 * one: a nominal scenario that still explains the run is no evidence of a fault. So the verdict is the one
 * {@code watch} reaches at the end of the same log: faulty exactly when every nominal model is out and a faulty one
 * still matches, and no match exactly when every model is out.
 */
public final class Classifier {

    /**
     * One model's score.
     *
     * @param model         the model
     * @param deleted       it could not take some input (the thesis's KeyError)
     * @param discrepancies outputs that differed (over the steps it walked)
     * @param failure       the input it could not take, or its first difference, or null
     */
    public record Score(LearnedModel model, boolean deleted, int discrepancies, ModelTracker.Failure failure) {
    }

    /**
     * The classification.
     *
     * @param scores every model, in model order
     * @param best   the best match within the threshold (nominal before faulty, then fewest discrepancies, then model
     *               order), if any
     */
    public record Result(List<Score> scores, Optional<Score> best) {

        /**
         * Whether the best match is a faulty scenario (the thesis's Warning_Procedure): every nominal model is out
         * and a faulty one matches.
         */
        public boolean faulty() {
            return best.map(s -> s.model().faulty()).orElse(false);
        }
    }

    private Classifier() {
    }

    /** Classifies a complete trace. {@code threshold}: most discrepancies a match may have. */
    public static Result classify(ModelSet models, MealyTrace trace, int threshold) {
        List<Score> scores = new ArrayList<>();
        for (LearnedModel m : models.models()) {
            Verification v = Verification.of(m, trace);
            boolean deleted = v.verdict() == Verification.Verdict.INPUT_UNDEFINED;
            scores.add(new Score(m, deleted, v.discrepancies(), v.failure()));
        }
        // A nominal model that still matches is not evidence of a fault, even with more discrepancies: prefer it.
        Optional<Score> best = scores.stream()
                .filter(s -> !s.deleted() && s.discrepancies() <= threshold)
                .min(Comparator.comparing((Score s) -> s.model().faulty()).thenComparingInt(Score::discrepancies));
        return new Result(List.copyOf(scores), best);
    }
}
