package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Verification;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.pipeline.Traces;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;

/** {@code predmon verify}: Algorithm 6, does a scenario's model reproduce a log? */
@Command(name = "verify", mixinStandardHelpOptions = true,
        description = {"Run a log's trace through the models of one scenario (thesis Algorithm 6) and report the "
                + "thesis's case: 1 matches; 2 outputs differ (first position and both symbols); "
                + "3 an input the model cannot take (position and symbol).",
                "Exit 0 when some machine of the scenario matches, 1 otherwise."})
final class VerifyCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--log", required = true, paramLabel = "FILE", description = "The log to verify.")
    Path log;

    @Option(names = "--scenario", required = true, paramLabel = "NAME", description = "The scenario whose models to use.")
    String scenario;

    @Mixin
    ModelOptions models;

    @Mixin
    AbstractionOption abstractionOption;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        Abstraction abstraction = abstractionOption.load();
        ModelSet set = models.load(abstraction);
        abstraction = set.tune(abstraction); // the hysteresis learn estimated from the training runs' sensor noise
        List<LearnedModel> own = set.models().stream().filter(m -> m.scenario().equals(scenario)).toList();
        if (own.isEmpty()) {
            throw new BadInputException(models.dir + ": no scenario '" + scenario + "' (have: "
                    + String.join(", ", set.index().scenarios().stream().map(s -> s.name()).toList()) + ")");
        }
        LogTrace trace = Traces.read(log, abstraction);
        Problems.print(spec.commandLine().getErr(), log, trace);
        // A log of several runs (the tick counter started again) is verified run by run; it matches when each does.
        List<MealyTrace> runs = trace.runs().size() > 1 ? trace.samples(RunLabel.ALL) : List.of(trace.mealy());
        boolean matched = true;
        for (MealyTrace mealy : runs) {
            out.println(mealy.source() + ": " + mealy.length() / 2 + " compacted pairs, " + mealy.length() + " Mealy steps");
            boolean any = false;
            for (LearnedModel m : own) {
                Verification v = Verification.of(m, mealy);
                any |= v.verdict() == Verification.Verdict.MATCHES;
                out.println("  " + m.id() + ": " + describe(v));
            }
            matched &= any;
        }
        out.println(matched ? "matches scenario " + scenario : "does not match scenario " + scenario);
        out.flush();
        return matched ? ExitCodes.OK : ExitCodes.WARNING;
    }

    static String describe(Verification v) {
        return switch (v.verdict()) {
            case MATCHES -> "case 1, matches (" + v.steps() + " steps)";
            case OUTPUTS_DIFFER -> "case 2, outputs differ " + v.discrepancies() + " time(s); first: "
                    + v.failure().describe();
            case INPUT_UNDEFINED -> "case 3, " + v.failure().describe();
        };
    }
}
