package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.evaluate.Confusion;
import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.Evaluator;
import dev.predmon.evaluate.HtmlReport;
import dev.predmon.evaluate.RunResult;
import dev.predmon.evaluate.ScenarioSummary;
import dev.predmon.evaluate.Stats;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioSpec;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;

/** {@code predmon evaluate}: how often the monitor warns, how early, and how often wrongly. */
@Command(name = "evaluate", mixinStandardHelpOptions = true,
        description = {"Measure the predictive monitor on your own runs before trusting it: learn as 'learn' does "
                + "(in memory, nothing is written) and replay each test log exactly as 'watch --no-follow' would, "
                + "built-in safety monitor included.",
                "With --test DIR: learn on --logs, judge every log of DIR. With --folds K (default 5): K-fold "
                        + "cross-validation over --logs, run by run; a log is only judged by models learned without it.",
                "Prints per scenario: runs, warned, hits, false alarms, missed (a faulty run not warned before its "
                        + "violation), lead (violation time - warning time) and battery at the warning "
                        + "(median [min..max]); then every run's verdict."})
final class EvaluateCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--logs", required = true, paramLabel = "DIR",
            description = "Training logs, in the 'learn' layout (<scenario>/scenario.json and *.log).")
    Path logs;

    @ArgGroup(exclusive = true)
    Split split;

    static final class Split {
        @Option(names = "--test", paramLabel = "DIR", description = "Test logs, same layout as --logs.")
        Path test;

        @Option(names = "--folds", paramLabel = "K", description = "Cross-validation folds (default: 5).")
        Integer folds;
    }

    @Mixin
    ThresholdOption threshold;

    @Mixin
    ConfirmOption confirm;

    @Mixin
    RuleOption rule;

    @Option(names = "--report", paramLabel = "FILE",
            description = "Write a self-contained HTML report: table, confusion matrix, leads, battery plots, models.")
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
        Abstraction abstraction = abstractionOption.load();
        List<ScenarioSpec> train = ScenarioLayout.scan(logs, abstraction);
        Evaluator evaluator = new Evaluator(abstraction, threshold.value, confirm.value(abstraction),
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
            printTables(out, e);
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

    private static void printTables(PrintWriter out, Evaluation e) {
        out.println(e.mode().equals("cross-validation")
                ? e.folds() + "-fold cross-validation, threshold " + e.threshold() + ", abstraction '" + e.abstraction() + "'"
                : "learned on --logs, judged --test, threshold " + e.threshold() + ", abstraction '" + e.abstraction() + "'");
        out.println();
        String head = "%-14s %-8s %5s %6s %5s %6s %6s %5s %6s %8s %6s  %-34s %-28s%n";
        out.printf(Locale.ROOT, head, "scenario", "kind", "runs", "warned", "hits", "false", "missed", "late",
                "no-vio", "no-match", "sudden", "lead: median [min..max]", "battery@warning: median [min..max]");
        for (ScenarioSummary s : e.scenarios()) {
            out.printf(Locale.ROOT, head, s.scenario(), s.faulty() ? "faulty" : "nominal", s.runs(), s.warned(),
                    s.hits(), s.falseAlarms(), s.missed(), s.late(), s.noViolation(), s.noMatch(), s.sudden(),
                    s.lead().n() == 0 ? "-" : stats(s.lead()) + " " + s.leadUnit(), stats(s.batteryAtWarning()));
        }
        out.println();
        out.println("sudden: runs whose violation came in one reading from more than " + RunResult.SUDDEN_MARGIN
                + " points above the threshold (the violation is the jump itself: no monitor can see it coming)");
        Confusion c = e.confusion();
        out.println();
        out.printf(Locale.ROOT, "confusion (actual x predicted): faulty&warned-in-time %d, faulty&missed %d, "
                        + "nominal&warned %d, nominal&quiet %d; faulty without violation (unscored) %d%n",
                c.truePositives(), c.falseNegatives(), c.falsePositives(), c.trueNegatives(), c.unscored());
        out.printf(Locale.ROOT, "recall %s, false-alarm rate %s (warning rule: %s)%n", percent(c.recall()),
                percent(c.falseAlarmRate()), e.rule());
        ForecastTables.print(out, e);
        out.println();
        out.println();
        out.printf(Locale.ROOT, "%-14s %-28s %4s %-23s %9s %9s %8s %-5s %6s %6s  %s%n", "scenario", "log", "fold",
                "verdict", "warning", "violation", "lead", "unit", "P@warn", "P-peak", "eliminated (model@line)");
        for (RunResult r : e.runs()) {
            String elim = r.eliminations().stream().map(x -> x.model() + "@" + x.line()).collect(Collectors.joining(" "));
            out.printf(Locale.ROOT, "%-14s %-28s %4s %-23s %9s %9s %8s %-5s %6s %6s  %s%s%s%n", r.scenario(),
                    Path.of(r.log()).getFileName(), r.fold() < 0 ? "-" : Integer.toString(r.fold()), r.verdict().id(),
                    num(r.warningTime()), num(r.violationTime()), num(r.lead()), r.unit(),
                    r.forecast() == null || r.forecast().atWarning() == null ? "-"
                            : num(r.forecast().atWarning().probability()),
                    r.forecast() == null ? "-" : num(r.forecast().peak()), elim,
                    r.noMatch() ? " [no-match]" : "", r.sudden() ? " [sudden violation]" : "");
        }
    }

    private static String stats(Stats s) {
        return s.n() == 0 ? "-" : String.format(Locale.ROOT, "%.1f [%.1f..%.1f]", s.median(), s.min(), s.max());
    }

    private static String num(Double d) {
        return d == null ? "-" : String.format(Locale.ROOT, "%.2f", d);
    }

    private static String percent(Double d) {
        return d == null ? "-" : String.format(Locale.ROOT, "%.1f%%", d * 100);
    }
}
