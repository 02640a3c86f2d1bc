package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.evaluate.Explanation;
import dev.predmon.model.ModelSet;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code predmon explain}: why did it warn, why did it not. */
@Command(name = "explain", mixinStandardHelpOptions = true,
        description = {"Explain a run: its abstract trace pair by pair and, for each model, where it stopped "
                + "matching and why (the reply it expected versus the one seen), then what 'watch' concluded.",
                "Exit 1 when watch would warn on this log, 0 otherwise."})
final class ExplainCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--log", required = true, paramLabel = "FILE", description = "The log to explain.")
    Path log;

    @Mixin
    ThresholdOption threshold;

    @Mixin
    ConfirmOption confirm;

    @Option(names = "--json", description = "Print the explanation as one JSON document.")
    boolean json;

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
        if (!Files.isRegularFile(log)) {
            throw new BadInputException(log + ": no such file");
        }
        List<Explanation> runs = Explanation.of(log, set, abstraction, threshold.value, confirm.value(abstraction));
        if (json) {
            // One object for a log of one run, as always; a log of several runs gives one object per run.
            Object value = runs.size() == 1 ? runs.get(0) : java.util.Map.of("runs", runs);
            out.println(new com.fasterxml.jackson.databind.ObjectMapper()
                    .enable(com.fasterxml.jackson.databind.SerializationFeature.INDENT_OUTPUT).writeValueAsString(value));
        } else {
            for (int i = 0; i < runs.size(); i++) {
                if (i > 0) {
                    out.println();
                }
                print(out, runs.get(i));
            }
        }
        out.flush();
        return runs.stream().anyMatch(x -> x.run().warningTime() != null) ? ExitCodes.WARNING : ExitCodes.OK;
    }

    private static void print(PrintWriter out, Explanation x) {
        out.println("trace of " + x.log() + " (" + x.steps().size() + " compacted pairs):");
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
        out.println(r.violationTime() == null ? "the safety property holds throughout the log"
                : String.format(Locale.ROOT, "the safety property is violated at t=%.3f", r.violationTime()));
    }
}
