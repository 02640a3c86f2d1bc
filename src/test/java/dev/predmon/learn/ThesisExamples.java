package dev.predmon.learn;

import dev.predmon.mealy.MealyTrace;
import net.automatalib.word.Word;

import java.util.Arrays;

/** Worked examples of the thesis as Mealy samples. */
final class ThesisExamples {

    private ThesisExamples() {
    }

    /** Figure 4.10: the compacted trace of Figure 4.8b mapped to Mealy words. */
    static MealyTrace figure410() {
        return trace("fig4.10",
                "level_i Delta batteryStatus_i Delta isAt_ki_i Delta goTo_ki_i Delta",
                "OK o_level_high OK o_batteryStatus_false OK o_isAt_ki_false OK o_goto_ki");
    }

    static MealyTrace trace(String source, String inputs, String outputs) {
        return new MealyTrace(Word.fromList(Arrays.asList(inputs.split(" "))),
                Word.fromList(Arrays.asList(outputs.split(" "))), source);
    }

    /** One letter per symbol: {@code chars("abab")} = a b a b. */
    static MealyTrace chars(String source, String inputs, String outputs) {
        return trace(source, String.join(" ", inputs.split("")), String.join(" ", outputs.split("")));
    }
}
