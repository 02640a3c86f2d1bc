package dev.predmon.mealy;

import net.automatalib.word.Word;

/**
 * A compacted interface trace as a Mealy sample: the input word and the output word of equal length.
 *
 * @param inputs  {@code in1 Delta in2 Delta ...}
 * @param outputs {@code OK out1 OK out2 ...}
 * @param source  where it came from (a log path), for messages
 */
public record MealyTrace(Word<String> inputs, Word<String> outputs, String source) {

    public MealyTrace {
        if (inputs.length() != outputs.length()) {
            throw new IllegalArgumentException("input and output words differ in length: " + inputs.length()
                    + " vs " + outputs.length());
        }
    }

    /** Number of Mealy steps (twice the number of I/O pairs). */
    public int length() {
        return inputs.length();
    }

    /** Number of I/O pairs the trace encodes. */
    public int pairs() {
        return inputs.length() / 2;
    }
}
