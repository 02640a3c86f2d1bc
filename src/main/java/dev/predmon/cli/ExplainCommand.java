package dev.predmon.cli;

import dev.predmon.explain.Explanation;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;

/** {@code predmon explain}: why did it warn, why did it not. */
@Command(name = "explain", mixinStandardHelpOptions = true,
        description = {"Explain a run: its abstract trace pair by pair and, for each model, where it stopped "
                + "matching and why (the reply it expected versus the one seen), then what 'watch' concluded.",
                "Exit as watch --no-follow would on this log: 1 when it warns, 5 when no model matches the run, 0 "
                        + "otherwise; 3 when the log holds nothing to judge."})
final class ExplainCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    ConfirmOption confirm;

    @Mixin
    LogAgainstModels input;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        LogAgainstModels.Opened in = input.open(spec.commandLine().getErr());
        List<Explanation> runs = Explanation.of(in.trace(), in.models(), in.abstraction(), input.threshold(),
                confirm.value(in.abstraction()));
        if (input.json) {
            // One document for a log of one run, as always; a log of several runs gives one per run.
            out.println(Json.document(runs.size() == 1 ? runs.get(0) : Map.of("runs", runs)));
        } else {
            for (int i = 0; i < runs.size(); i++) {
                if (i > 0) {
                    out.println();
                }
                print(out, runs.get(i));
            }
        }
        out.flush();
        return ExitCodes.ofRuns(runs.stream().mapToInt(x -> ExitCodes.of(x.run().noMatch(), x.run().warningTime() != null)));
    }

    private static void print(PrintWriter out, Explanation x) {
        out.println("trace of " + Terminal.line(x.log()) + " (" + x.steps().size() + " compacted pairs):");
        for (Explanation.Step s : x.steps()) {
            StringBuilder ends = new StringBuilder();
            for (Explanation.ModelFate f : x.models()) {
                if (f.stoppedAt() != null && f.stoppedAt() == s.index()) {
                    ends.append(ends.length() == 0 ? "   <- eliminated: " : ", ").append(f.model());
                }
            }
            out.printf(Locale.ROOT, "  %4d  t=%-10.3f line %-7d %s -> %s%s%n", s.index(), s.time(), s.line(),
                    s.input(), s.output(), ends);
        }
        out.println();
        out.println("models:");
        for (Explanation.ModelFate f : x.models()) {
            out.printf(Locale.ROOT, "  %-16s %-8s %s%n", f.model(), f.faulty() ? "faulty" : "nominal",
                    f.matched() ? f.reason() : "stopped at pair " + f.stoppedAt() + ": " + f.reason());
        }
        out.println();
        var r = x.run();
        if (r.warningTime() != null) {
            out.printf(Locale.ROOT, "watch WARNS at t=%.3f (line %d): every nominal model is eliminated while %s "
                    + "still matches%n", r.warningTime(), r.warningLine(), String.join(", ", r.warningScenarios()));
        } else {
            boolean nominal = x.models().stream().anyMatch(f -> !f.faulty() && f.matched());
            boolean faulty = x.models().stream().anyMatch(f -> f.faulty() && f.matched());
            out.println("watch does not warn: " + (nominal ? "a nominal model matches the whole run"
                    : faulty ? "a nominal model matched until the faulty ones were gone"
                    : "no model was left when the nominal ones were eliminated"));
        }
        if (r.noMatch()) {
            out.println("no model matches the whole run: it is unlike every learned scenario (no prediction)");
        }
        out.println(r.violationTime() != null
                ? String.format(Locale.ROOT, "the safety property is violated at t=%.3f", r.violationTime())
                : r.safetyObserved() ? "the safety property holds throughout the log"
                : "the safety property is not observed in the log (no value for it): no verdict on it");
    }
}
