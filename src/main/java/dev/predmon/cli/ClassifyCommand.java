package dev.predmon.cli;

import dev.predmon.Terminal;
import dev.predmon.event.OutcomeJson;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Classifier;
import dev.predmon.monitor.PropertyOutcome;
import dev.predmon.pipeline.RunId;
import dev.predmon.replay.LogReplay;
import dev.predmon.replay.ReplayedLog;
import dev.predmon.replay.ReplayedRun;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.function.DoubleFunction;

/** {@code predmon classify}: Algorithm 7 on a complete log. */
@Command(name = "classify", mixinStandardHelpOptions = true,
        description = {"Classify a complete log against every model (thesis Algorithm 7): discrepancies per model, "
                + "the models eliminated (an input they cannot take, or more discrepancies than --tolerance), the "
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
        ModelSet set = input.models();
        PrintWriter out = spec.commandLine().getOut();
        // One replay through watch's monitor, with its default rule and confirmation: its verdict is watch's, and
        // Algorithm 7 scores the pairs it took. Its forecasts are not kept: a long log's replay stays small.
        ReplayedLog replayed = input.replay(spec.commandLine().getErr(), input.tuned().confirm(), (r, run, judged) -> { },
                LogReplay.Detail.VERDICTS);
        int code = ExitCodes.ofMonitor(replayed.monitor());
        // A log of several runs (the tick counter started again) is classified run by run.
        List<ReplayedRun> runs = replayed.runs().size() > 1
                ? replayed.runs().stream().filter(r -> !r.pairs().isEmpty()).toList() : replayed.runs();
        List<Result> results = new ArrayList<>();
        for (ReplayedRun run : runs) {
            String name = RunId.of(replayed.log(), run.run(), replayed.runs().size()).name();
            Classifier.Result r = Classifier.classify(set, run.pairs().stream().map(ReplayedRun.Pair::pair).toList(),
                    input.tolerance());
            if (input.json) {
                List<Score> scores = r.scores().stream().map(s -> new Score(s.model().id(), s.model().scenario(),
                        s.model().faulty(), s.eliminated(), s.discrepancies(),
                        s.failure() == null ? null : s.failure().describe())).toList();
                results.add(new Result(name, run.pairs().size(), scores,
                        r.best().map(s -> s.model().id()).orElse(null),
                        r.best().map(s -> s.model().scenario()).orElse(null), r.faulty(), run.violated(), code,
                        OutcomeJson.of(PropertyOutcome.of(run.outcome(),
                                replayed.monitor().forecastProperty().orElse(null)))));
            } else {
                print(out, r, name, run.pairs().size());
            }
        }
        if (input.json) {
            out.println(Json.line(results.size() == 1 ? results.get(0) : new Runs(input.log().toString(), results)));
        } else {
            // per property, worst first, every run of the log together: what was violated and warned, then the rest
            String forecastId = replayed.monitor().forecastProperty().orElse(null);
            List<PropertyOutcome> outcome = PropertyOutcome.worstOver(replayed.runs().stream()
                    .map(r -> PropertyOutcome.of(r.outcome(), forecastId)).toList());
            DoubleFunction<String> span = l -> String.format(Locale.ROOT, "%.3f %s", l, replayed.unit());
            out.println("watch's verdict at the end of the log: "
                    + PropertyOutcome.sentence(outcome, replayed.monitor().summary().warned(), span)
                    + (code == ExitCodes.NO_MATCH ? "; " + words(code) : "") + " (exit " + code + ")");
        }
        out.flush();
        return code;
    }

    private static String words(int code) {
        return switch (code) {
            case ExitCodes.UNWARNED_VIOLATION -> "a property was violated with no warning before it";
            case ExitCodes.WARNING -> "a warning was raised";
            case ExitCodes.NO_MATCH -> "no learned model matches the run";
            default -> "no warning, and a nominal model matches";
        };
    }

    private void print(PrintWriter out, Classifier.Result r, String run, int pairs) {
        out.println(Terminal.line(run) + ": " + pairs + " compacted pairs");
        for (Classifier.Score s : r.scores()) {
            out.printf("  %-16s %-8s %s%n", s.model().id(), s.model().faulty() ? "faulty" : "nominal",
                    VerifyCommand.fate(s.failure(), s.discrepancies(), s.eliminated()));
        }
        out.println(r.best().map(s -> "best match: " + s.model().scenario() + " (" + s.model().id() + ", "
                + s.discrepancies() + " discrepancies)" + (s.model().faulty() ? ": FAULTY" : ""))
                .orElse("no model matches within tolerance " + input.tolerance()
                        + ": the run is unlike every learned scenario"));
    }

    /** The {@code --json} document of a log that holds several runs: one result per run. */
    record Runs(String log, List<Result> runs) {
    }

    /** One model's score in {@code --json}. */
    record Score(String model, String scenario, boolean faulty, boolean eliminated, int discrepancies,
                 String reason) {
    }

    /**
     * The {@code --json} document: {@code outcome} per property, worst first; {@code violated} is the forecast
     * property's alone (a deprecated alias, kept for one release).
     */
    record Result(String log, int pairs, List<Score> models, String best, String scenario, boolean faulty,
                  boolean violated, int watchExit, OutcomeJson outcome) {
    }
}
