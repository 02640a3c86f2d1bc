package dev.predmon.cli;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code --tolerance N}, the discrepancy tolerance, shared by the commands that match logs against models (thesis
 * Algorithms 7 and 8): not to be confused with the forecast's probability threshold or a property's bound.
 */
final class ToleranceOption {

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    int value;

    @Option(names = "--tolerance", paramLabel = "N", defaultValue = "0",
            description = "Discrepancy tolerance: output discrepancies a model may accumulate and still match; one "
                    + "more drops it (default: ${DEFAULT-VALUE}, exact matching). An input a model cannot take always "
                    + "drops it.")
    void set(int n) {
        set(n, "--tolerance");
    }

    /** The option's earlier name, still taken so that existing scripts keep working. */
    @Option(names = "--threshold", paramLabel = "N", hidden = true)
    void setOldName(int n) {
        set(n, "--threshold");
    }

    private void set(int n, String name) {
        if (n < 0) {
            throw new ParameterException(mixee.commandLine(), name + " must be at least 0, got " + n);
        }
        value = n;
    }
}
