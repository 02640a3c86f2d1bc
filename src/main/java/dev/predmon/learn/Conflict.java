package dev.predmon.learn;

import dev.predmon.mealy.MealyTrace;
import net.automatalib.word.Word;

/**
 * Two samples that one Mealy machine cannot both hold: after the same inputs they answer differently.
 *
 * @param first    one sample
 * @param second   the other
 * @param position index (0-based, in Mealy steps) of the first differing output
 * @param prefix   the common inputs up to and including that step
 * @param firstOutput  the first sample's output there
 * @param secondOutput the second sample's output there
 */
public record Conflict(MealyTrace first, MealyTrace second, int position, Word<String> prefix,
                       String firstOutput, String secondOutput) {

    /**
     * The conflict between two samples, or null when they agree on every common input prefix. Mealy
     * machines are deterministic, so one such position makes the pair unlearnable together; agreement on
     * every common prefix makes it learnable (the prefix tree of the two is consistent).
     */
    public static Conflict between(MealyTrace a, MealyTrace b) {
        Word<String> ai = a.inputs();
        Word<String> bi = b.inputs();
        int n = Math.min(ai.length(), bi.length());
        for (int i = 0; i < n; i++) {
            if (!ai.getSymbol(i).equals(bi.getSymbol(i))) {
                return null;
            }
            String ao = a.outputs().getSymbol(i);
            String bo = b.outputs().getSymbol(i);
            if (!ao.equals(bo)) {
                return new Conflict(a, b, i, ai.prefix(i + 1), ao, bo);
            }
        }
        return null;
    }

    /** One line for users: both logs, where they disagree and how. */
    public String describe() {
        int shown = Math.min(prefix.length(), 8);
        String tail = prefix.suffix(shown).stream().reduce((x, y) -> x + " " + y).orElse("");
        return first.source() + " and " + second.source() + " disagree at step " + position + " (after "
                + (prefix.length() > shown ? "... " : "") + tail + "): " + firstOutput + " vs " + secondOutput;
    }
}
