package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.Terminal;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Classifier;
import dev.predmon.monitor.LogWatcher;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.pipeline.LogTrace;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/** {@code predmon classify}: Algorithm 7 on a complete log. */
@Command(name = "classify", mixinStandardHelpOptions = true,
        description = {"Classify a complete log against every model (thesis Algorithm 7): discrepancies per model, "
                + "the models eliminated (an input they cannot take, or more discrepancies than --threshold), the "
                + "best match and whether it is faulty.",
                "Then the verdict watch reaches at the end of the same log, from the same replay: its exit code is "
                        + "classify's. Exit 6 when a property is violated with no warning before it, else 1 when a "
                        + "warning came, 5 when no model matches the run at its end, 0 otherwise; 3 when the log holds "
                        + "nothing to judge."})
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
        int code = watchCode(set, in.abstraction());
        // A log of several runs (the tick counter started again) is classified run by run.
        List<MealyTrace> runs = in.trace().judgedRuns();
        List<LogTrace.Run> inFull = in.trace().judgedRunsInFull();
        List<Result> results = new ArrayList<>();
        for (int i = 0; i < runs.size(); i++) {
            MealyTrace run = runs.get(i);
            Classifier.Result r = Classifier.classify(set, run, input.threshold());
            boolean violated = i < inFull.size() && inFull.get(i).violated();
            if (input.json) {
                List<Score> scores = r.scores().stream().map(s -> new Score(s.model().id(), s.model().scenario(),
                        s.model().faulty(), s.eliminated(), s.discrepancies(),
                        s.failure() == null ? null : s.failure().describe())).toList();
                results.add(new Result(run.source(), run.pairs(), scores,
                        r.best().map(s -> s.model().id()).orElse(null),
                        r.best().map(s -> s.model().scenario()).orElse(null), r.faulty(), violated, code));
            } else {
                print(out, r, run);
            }
        }
        if (input.json) {
            out.println(Json.line(results.size() == 1 ? results.get(0) : new Runs(input.log().toString(), results)));
        } else {
            out.println("watch's verdict at the end of the log: " + words(code) + " (exit " + code + ")");
        }
        out.flush();
        return code;
    }

    /**
     * The code {@code watch --no-follow} gives this log: the log replayed through watch's own monitor, with its
     * default rule and confirmation, so that the two commands cannot disagree.
     */
    private int watchCode(ModelSet set, Abstraction abstraction) throws IOException, BadInputException {
        PredictiveMonitor m = new PredictiveMonitor(set, abstraction, input.threshold(), abstraction.confirm(),
                PredictiveMonitor.defaultRule(set), e -> { });
        try (LogWatcher w = LogWatcher.withRecords(input.log(), m, p -> { }, r -> { })) {
            w.drain();
        }
        return ExitCodes.ofMonitor(m);
    }

    private static String words(int code) {
        return switch (code) {
            case ExitCodes.UNWARNED_VIOLATION -> "a property was violated with no warning before it";
            case ExitCodes.WARNING -> "a warning was raised";
            case ExitCodes.NO_MATCH -> "no learned model matches the run";
            default -> "no warning, and a nominal model matches";
        };
    }

    private void print(PrintWriter out, Classifier.Result r, MealyTrace run) {
        out.println(Terminal.line(run.source()) + ": " + run.pairs() + " compacted pairs");
        for (Classifier.Score s : r.scores()) {
            out.printf("  %-16s %-8s %s%n", s.model().id(), s.model().faulty() ? "faulty" : "nominal",
                    VerifyCommand.fate(s.failure(), s.discrepancies(), s.eliminated()));
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
    record Score(String model, String scenario, boolean faulty, boolean eliminated, int discrepancies,
                 String reason) {
    }

    /** The {@code --json} document. */
    record Result(String log, int pairs, List<Score> models, String best, String scenario, boolean faulty,
                  boolean violated, int watchExit) {
    }
}
