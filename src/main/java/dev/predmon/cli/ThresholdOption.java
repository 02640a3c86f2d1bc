package dev.predmon.cli;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code --threshold N}, shared by the commands that match logs against models (thesis Algorithms 7 and 8). */
final class ThresholdOption {

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    int value;

    @Option(names = "--threshold", paramLabel = "N", defaultValue = "0",
            description = "Output discrepancies a model may accumulate and still match; one more drops it "
                    + "(default: ${DEFAULT-VALUE}, exact matching). An input a model cannot take always drops it.")
    void set(int n) {
        if (n < 0) {
            throw new ParameterException(mixee.commandLine(), "--threshold must be at least 0, got " + n);
        }
        value = n;
    }
}
