package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.Evaluator;
import dev.predmon.files.OutputFiles;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.report.HtmlReport;
import dev.predmon.report.TextReport;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/** {@code predmon evaluate}: how often the monitor warns, how early, and how often wrongly. */
@Command(name = "evaluate", mixinStandardHelpOptions = true,
        description = {"Measure the predictive monitor on your own runs before trusting it: learn as 'learn' does "
                + "(in memory, nothing is written) and replay each test log exactly as 'watch --no-follow' would, "
                + "built-in safety monitor included.",
                "With --test DIR: learn on --logs, judge every log of DIR. With --folds K (default 5): K-fold "
                        + "cross-validation over --logs, run by run; a log is only judged by models learned without it.",
                "Prints per scenario: runs, warned, hits, false alarms, missed (a faulty run not warned before its "
                        + "violation), lead (violation time - warning time) and the watched value at the warning "
                        + "(median [min..max]); then every run's verdict."})
final class EvaluateCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--logs", required = true, paramLabel = "DIR",
            description = "Training logs, in either layout 'learn' takes: one folder per scenario "
                    + "(<scenario>/scenario.json and *.log), or a folder of recordings not sorted into scenarios, "
                    + "whose runs the safety monitor labels (docs/logs.md).")
    Path logs;

    @ArgGroup(exclusive = true)
    Split split;

    static final class Split {
        @Option(names = "--test", paramLabel = "DIR", description = "Test logs, same layout as --logs.")
        Path test;

        @Option(names = "--folds", paramLabel = "K", description = "Cross-validation folds (default: 5); as many as the logs or more: "
                + "leave-one-out.")
        Integer folds;
    }

    @Mixin
    ToleranceOption tolerance;

    @Mixin
    ConfirmOption confirm;

    @Mixin
    RuleOption rule;

    @Option(names = "--report", paramLabel = "FILE",
            description = "Write a self-contained HTML report: table, confusion matrix, leads, plots of the watched "
                    + "value, models.")
    Path report;

    @Option(names = "--json", description = "Print the evaluation as one JSON document instead of tables.")
    boolean json;

    @Option(names = "--quiet", description = "No progress indicator on stderr.")
    boolean quiet;

    @Mixin
    AbstractionOption abstractionOption;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (report != null) {
            // before the minutes of learning and replay: a report that could not be written would waste them
            List<OutputFiles.Input> inputs = new ArrayList<>(abstractionOption.inputs());
            inputs.add(new OutputFiles.Input(logs, "--logs"));
            if (split != null && split.test != null) {
                inputs.add(new OutputFiles.Input(split.test, "--test"));
            }
            OutputFiles.requireReplaceable(report, "--report", HtmlReport.SIGNATURE, "an evaluate report", inputs);
        }
        Abstraction abstraction = abstractionOption.load();
        List<ScenarioSpec> train = ScenarioLayout.scan(logs, abstraction);
        Evaluator evaluator = new Evaluator(abstraction, tolerance.value, confirm.value(abstraction),
                ProgressBar.on(err, quiet)).rule(rule.asked());
        Evaluation e;
        if (split != null && split.test != null) {
            e = evaluator.trainTest(train, ScenarioLayout.scan(split.test, abstraction));
        } else {
            int k = split == null || split.folds == null ? 5 : split.folds;
            if (k < 2) {
                throw new ParameterException(spec.commandLine(), "--folds must be at least 2, got " + k);
            }
            e = evaluator.crossValidate(train, k);
        }
        e.notes().forEach(n -> err.println("predmon: note: " + n));
        err.flush();
        if (json) {
            out.println(toJson(e));
        } else {
            TextReport.print(out, e);
        }
        if (report != null) {
            HtmlReport.write(e, abstraction, report);
            (json ? err : out).println("wrote " + report);
        }
        out.flush();
        err.flush();
        return ExitCodes.OK;
    }

    static String toJson(Evaluation e) {
        return Json.document(e);
    }
}
