package dev.predmon.cli;

import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Classifier;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/** {@code predmon classify}: Algorithm 7 on a complete log. */
@Command(name = "classify", mixinStandardHelpOptions = true,
        description = {"Classify a complete log against every model (thesis Algorithm 7): discrepancies per model, "
                + "models that could not take the trace, the best match and whether it is faulty.",
                "Exit 1 when the best match is a faulty scenario, 5 when no model matches, 0 otherwise; 3 when the "
                        + "log holds nothing to judge."})
final class ClassifyCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    LogAgainstModels input;

    @Override
    public Integer call() throws Exception {
        LogAgainstModels.Opened in = input.open(spec.commandLine().getErr());
        ModelSet set = in.models();
        PrintWriter out = spec.commandLine().getOut();
        // A log of several runs (the tick counter started again) is classified run by run.
        List<MealyTrace> runs = in.trace().judgedRuns();
        List<Result> results = new ArrayList<>();
        List<Integer> codes = new ArrayList<>();
        for (MealyTrace run : runs) {
            Classifier.Result r = Classifier.classify(set, run, input.threshold());
            codes.add(ExitCodes.of(r.best().isEmpty(), r.faulty()));
            if (input.json) {
                List<Score> scores = r.scores().stream().map(s -> new Score(s.model().id(), s.model().scenario(),
                        s.model().faulty(), s.deleted(), s.discrepancies(),
                        s.failure() == null ? null : s.failure().describe())).toList();
                results.add(new Result(run.source(), run.pairs(), scores,
                        r.best().map(s -> s.model().id()).orElse(null),
                        r.best().map(s -> s.model().scenario()).orElse(null), r.faulty()));
            } else {
                print(out, r, run);
            }
        }
        if (input.json) {
            out.println(Json.line(results.size() == 1 ? results.get(0) : new Runs(input.log().toString(), results)));
        }
        out.flush();
        return ExitCodes.ofRuns(codes.stream().mapToInt(Integer::intValue));
    }

    private void print(PrintWriter out, Classifier.Result r, MealyTrace run) {
        out.println(Terminal.line(run.source()) + ": " + run.pairs() + " compacted pairs");
        for (Classifier.Score s : r.scores()) {
            out.printf("  %-16s %-8s %s%n", s.model().id(), s.model().faulty() ? "faulty" : "nominal",
                    s.deleted() ? "deleted: " + s.failure().describe()
                            : s.discrepancies() + " discrepancies" + (s.failure() == null ? "" : "; first: " + s.failure().describe()));
        }
        out.println(r.best().map(s -> "best match: " + s.model().scenario() + " (" + s.model().id() + ", "
                + s.discrepancies() + " discrepancies)" + (s.model().faulty() ? ": FAULTY" : ""))
                .orElse("no model matches within threshold " + input.threshold()
                        + ": the run is unlike every learned scenario"));
    }

    /** The {@code --json} document of a log that holds several runs: one result per run. */
    record Runs(String log, List<Result> runs) {
    }

    /** One model's score in {@code --json}. */
    record Score(String model, String scenario, boolean faulty, boolean deleted, int discrepancies, String reason) {
    }

    /** The {@code --json} document. */
    record Result(String log, int pairs, List<Score> models, String best, String scenario, boolean faulty) {
    }
}
