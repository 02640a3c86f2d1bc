package dev.predmon.mealy;

/**
 * What walks a machine one Mealy step at a time; {@link MealyMapping#feedPair} feeds it a query/reply pair as its
 * two steps.
 *
 * @param <R> what a step answers
 */
public interface MealySteps<R> {

    /** Feeds one Mealy step: the input and the output observed for it. */
    R step(String input, String output);
}
