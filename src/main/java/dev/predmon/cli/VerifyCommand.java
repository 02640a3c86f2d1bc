package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.Terminal;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.matching.ModelTracker;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Verification;
import dev.predmon.pipeline.LogTrace;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/** {@code predmon verify}: Algorithm 6, does a scenario's model reproduce a log? */
@Command(name = "verify", mixinStandardHelpOptions = true,
        description = {"Run a log's trace through the models of one scenario (thesis Algorithm 6) and report for each "
                + "machine whether it matches, where its outputs differ (first position and both symbols), or where "
                + "it is eliminated: an input it cannot take (position and symbol), or more output differences than "
                + "--tolerance.",
                "Exit 0 when some machine of the scenario matches (outputs differing at most --tolerance times), 1 "
                        + "otherwise; 3 when the log holds nothing to judge."})
final class VerifyCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    LogAgainstModels input;

    @Option(names = "--scenario", required = true, paramLabel = "NAME", description = "The scenario whose models to use.")
    String scenario;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        ModelSet set = input.models();
        Abstraction abstraction = input.tuned();
        List<LearnedModel> own = set.models().stream().filter(m -> m.scenario().equals(scenario)).toList();
        if (own.isEmpty()) {
            throw new BadInputException(input.modelsDir + ": no scenario '" + scenario + "' (have: "
                    + String.join(", ", set.index().scenarios().stream().map(s -> s.name()).toList()) + ")");
        }
        LogTrace trace = input.readLog(abstraction, spec.commandLine().getErr());
        // A log of several runs (the tick counter started again) is verified run by run; it matches when each does.
        List<MealyTrace> runs = trace.judgedRuns();
        boolean all = true;
        List<Result> results = new ArrayList<>();
        for (MealyTrace mealy : runs) {
            boolean matched = false;
            List<Machine> machines = new ArrayList<>();
            for (LearnedModel m : own) {
                Verification v = Verification.of(m, mealy);
                boolean matches = v.verdict() == Verification.Verdict.MATCHES
                        || (v.verdict() == Verification.Verdict.OUTPUTS_DIFFER && v.discrepancies() <= input.tolerance());
                matched |= matches;
                machines.add(new Machine(m.id(), thesisCase(v.verdict()), matches, v.steps(), v.discrepancies(),
                        describe(v, input.tolerance())));
            }
            all &= matched;
            results.add(new Result(mealy.source(), scenario, mealy.pairs(), mealy.length(), machines, matched));
            if (!input.json) {
                out.println(Terminal.line(mealy.source()) + ": " + mealy.pairs() + " compacted pairs, " + mealy.length()
                        + " Mealy steps");
                machines.forEach(m -> out.println("  " + m.model() + ": " + m.reason()));
                if (runs.size() > 1) {
                    out.println("  " + (matched ? "matches" : "does not match") + " scenario " + scenario);
                }
            }
        }
        if (input.json) {
            out.println(Json.line(results.size() == 1 ? results.get(0) : new Runs(input.log().toString(), results)));
        } else {
            out.println(all ? "matches scenario " + scenario : "does not match scenario " + scenario);
        }
        out.flush();
        return all ? ExitCodes.OK : ExitCodes.WARNING;
    }

    /** The {@code --json} document of a log that holds several runs: one result per run. */
    record Runs(String log, List<Result> runs) {
    }

    private static int thesisCase(Verification.Verdict v) {
        return switch (v) {
            case MATCHES -> 1;
            case OUTPUTS_DIFFER -> 2;
            case INPUT_UNDEFINED -> 3;
        };
    }

    /** One machine's verdict in the words watch, explain and classify use. */
    static String describe(Verification v, int tolerance) {
        return v.verdict() == Verification.Verdict.MATCHES ? "matches (" + v.steps() + " steps)"
                : fate(v.failure(), v.discrepancies(), v.verdict() == Verification.Verdict.INPUT_UNDEFINED
                || v.discrepancies() > tolerance);
    }

    /**
     * What became of a model that did not match a trace exactly, in the words every command uses: eliminated with its
     * reason, or matching with its discrepancies.
     *
     * @param failure       the input it could not take, or its first difference; null when it had none
     * @param discrepancies outputs that differed over the steps it walked
     * @param eliminated    it could not take an input, or its outputs differed more often than the tolerance allows
     */
    static String fate(ModelTracker.Failure failure, int discrepancies, boolean eliminated) {
        if (failure == null) {
            return discrepancies + " discrepancies";
        }
        String differ = "outputs differ " + discrepancies + " time(s); first: " + failure.describe();
        return eliminated ? "eliminated: " + (failure.expected() == null ? failure.describe() : differ)
                : "matches within --tolerance, " + differ;
    }

    /**
     * One machine's verdict in {@code --json}.
     *
     * @param thesisCase the thesis's case: 1 matches, 2 outputs differ, 3 an input it cannot take
     * @param matches    case 1, or case 2 within the tolerance
     */
    record Machine(String model, int thesisCase, boolean matches, int steps, int discrepancies, String reason) {
    }

    /** The {@code --json} document. */
    record Result(String log, String scenario, int pairs, int steps, List<Machine> machines, boolean matches) {
    }
}
