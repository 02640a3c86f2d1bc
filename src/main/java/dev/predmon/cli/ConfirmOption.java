package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code --confirm N}, shared by the commands that raise the predictive warning (watch, evaluate, explain). */
final class ConfirmOption {

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    private Integer value;

    @Option(names = "--confirm", paramLabel = "N",
            description = "Pairs a faulty model must still match after the last nominal model is eliminated before "
                    + "the warning (default: the abstraction's; 0 for thesis, 1 for scope-fetch). 0 is the thesis's "
                    + "Algorithm 8: the earliest warning, but a nominal run unlike every training run can raise it.")
    void set(int n) {
        if (n < 0) {
            throw new ParameterException(mixee.commandLine(), "--confirm must be at least 0, got " + n);
        }
        value = n;
    }

    /** The value given, else the abstraction's. */
    int value(Abstraction abstraction) {
        return value != null ? value : abstraction.confirm();
    }
}
