package dev.predmon.monitor;

import dev.predmon.compact.IoPair;
import dev.predmon.matching.ModelTracker;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;

/**
 * Algorithm 7 of the thesis (MatchTraces), off-line: every model runs the whole trace; a model that cannot take
 * some input, or whose outputs differ more often than the tolerance allows, is eliminated (as {@code watch} eliminates
 * it; the thesis deletes it); every model gets its discrepancy count; the best match is the model with the fewest
 * discrepancies within the tolerance, except that a nominal model within the tolerance is preferred to any faulty
 * one: a nominal scenario that still explains the run is no evidence of a fault. So the verdict is the one
 * {@code watch} reaches at the end of the same log: faulty exactly when every nominal model is out and a faulty one
 * still matches, and no match exactly when every model is out.
 */
public final class Classifier {

    /**
     * One model's score.
     *
     * @param model         the model
     * @param eliminated    it could not take some input (the thesis's KeyError), or its outputs differed more often
     *                      than the tolerance allows
     * @param discrepancies outputs that differed (over the steps it walked)
     * @param failure       the input it could not take, or its first difference, or null
     */
    public record Score(LearnedModel model, boolean eliminated, int discrepancies, ModelTracker.Failure failure) {
    }

    /**
     * The classification.
     *
     * @param scores every model, in model order
     * @param best   the best match within the tolerance (nominal before faulty, then fewest discrepancies, then model
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

        /**
         * The pair after which the run could only be faulty, as {@code watch}'s matching would have warned there:
         * every nominal model eliminated, the last of them at that pair, while a faulty one still matched. Empty
         * when a nominal model matches to the end, or no faulty one outlived the nominal ones.
         */
        public OptionalInt onlyFaultyFrom() {
            int lastNominal = -1;
            for (Score s : scores) {
                if (!s.model().faulty()) {
                    if (!s.eliminated()) {
                        return OptionalInt.empty();
                    }
                    lastNominal = Math.max(lastNominal, pair(s));
                }
            }
            int last = lastNominal;
            boolean outlived = scores.stream().anyMatch(s -> s.model().faulty() && (!s.eliminated() || pair(s) > last));
            return outlived && last >= 0 ? OptionalInt.of(last) : OptionalInt.empty();
        }

        /** The pair at which an eliminated model's failure came. */
        private static int pair(Score s) {
            return s.failure() == null ? Integer.MAX_VALUE : MealyMapping.pairOfStep(s.failure().step());
        }
    }

    private Classifier() {
    }

    /**
     * Classifies a complete run given as its compacted pairs (as the replay of its log took them, so that the log is
     * read once). {@code tolerance}: most discrepancies a match may have.
     */
    public static Result classify(ModelSet models, List<IoPair> pairs, int tolerance) {
        List<Score> scores = new ArrayList<>();
        for (LearnedModel m : models.models()) {
            ModelTracker t = new ModelTracker(m, Integer.MAX_VALUE); // every discrepancy counted, as Algorithm 7 does
            for (IoPair p : pairs) {
                if (!t.pair(p.input(), p.output())) {
                    break;
                }
            }
            boolean undefined = !t.alive();
            boolean eliminated = undefined || t.discrepancies() > tolerance;
            scores.add(new Score(m, eliminated, t.discrepancies(), undefined ? t.elimination()
                    : t.firstDiscrepancy()));
        }
        // A nominal model that still matches is not evidence of a fault, even with more discrepancies: prefer it.
        Optional<Score> best = scores.stream()
                .filter(s -> !s.eliminated())
                .min(Comparator.comparing((Score s) -> s.model().faulty()).thenComparingInt(Score::discrepancies));
        return new Result(List.copyOf(scores), best);
    }
}
