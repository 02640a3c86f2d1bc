package dev.predmon.cli;

import dev.predmon.Terminal;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.evaluate.Approaches;
import dev.predmon.evaluate.RunResult;
import dev.predmon.event.ForecastJson;
import dev.predmon.event.OutcomeJson;
import dev.predmon.explain.Explanation;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.monitor.PropertyOutcome;
import dev.predmon.monitor.WarningRule;
import dev.predmon.replay.LogReplay;
import dev.predmon.replay.ReplayedLog;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.function.DoubleFunction;

/** {@code predmon explain}: why did it warn, why did it not. */
@Command(name = "explain", mixinStandardHelpOptions = true,
        description = {"Explain a run: its abstract trace pair by pair and, for each model, where it stopped "
                + "matching and why (the reply it expected versus the one seen), then what 'watch' concluded.",
                "Exit as watch --no-follow would on this log: 6 when a property is violated with no warning "
                        + "before it, else 1 when it warns, 5 when no model matches the run, 0 otherwise; 3 when the "
                        + "log holds nothing to judge."})
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
        Abstraction abstraction = input.tuned();
        Approaches approaches = Approaches.of(input.models(), abstraction);
        ReplayedLog replayed = input.replay(spec.commandLine().getErr(), confirm.value(abstraction), approaches::record,
                LogReplay.Detail.FORECASTS);
        List<Explanation> runs = Explanation.of(replayed, input.models(), abstraction, approaches);
        if (input.json) {
            // One document for a log of one run, as always; a log of several runs gives one per run.
            List<ExplanationJson> json = runs.stream().map(ExplanationJson::of).toList();
            out.println(Json.document(json.size() == 1 ? json.get(0) : Map.of("runs", json)));
        } else {
            for (int i = 0; i < runs.size(); i++) {
                if (i > 0) {
                    out.println();
                }
                print(out, runs.get(i), replayed.monitor().forecastProperty().orElse(null));
            }
        }
        out.flush();
        return ExitCodes.ofMonitor(replayed.monitor()); // watch's rule, on the monitor watch would have run
    }

    private static void print(PrintWriter out, Explanation x, String forecastId) {
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
            if (s.forecast() != null) {
                out.println("        " + ForecastWords.brief(s.forecast()));
            }
        }
        out.println();
        out.println("models:");
        for (Explanation.ModelFate f : x.models()) {
            out.printf(Locale.ROOT, "  %-16s %-8s %s%n", f.model(), f.faulty() ? "faulty" : "nominal",
                    f.matched() ? f.reason() : "eliminated at pair " + f.stoppedAt() + ": " + f.reason());
        }
        out.println();
        var r = x.run();
        Forecast last = r.forecast() == null ? null : r.forecast().last();
        boolean nominal = x.models().stream().anyMatch(f -> !f.faulty() && f.matched());
        int lastNominal = x.models().stream().filter(f -> !f.faulty() && f.stoppedAt() != null)
                .mapToInt(Explanation.ModelFate::stoppedAt).max().orElse(-1);
        boolean outlived = x.matchRuleAt() >= 0; // the monitor's own match rule, confirm included
        String matching = nominal ? "a nominal model matches the whole run"
                : outlived ? "every nominal model was eliminated by pair " + lastNominal + " while a faulty one still "
                + "matched (the thesis's rule holds from pair " + x.matchRuleAt() + ")"
                : lastNominal < 0 ? "the models hold no nominal scenario"
                : "every nominal model was eliminated by pair " + lastNominal + ", but no faulty one still matched "
                + "as many pairs after it as the rule confirms with";
        // the outcome first, worst property first: what was violated and warned, then the rest
        DoubleFunction<String> span = l -> String.format(Locale.ROOT, "%.3f %s", l, r.unit());
        List<String> hold = new ArrayList<>();
        for (PropertyOutcome p : x.outcome()) {
            if (p.rank() == PropertyOutcome.HOLDS) {
                hold.add(p.id());
            } else {
                out.println(p.words(span));
            }
        }
        if (!hold.isEmpty()) {
            out.println(String.join(", ", hold) + (hold.size() == 1 ? " holds" : " hold") + " throughout the log");
        }
        otherForecasts(out, r);
        String about = forecastId == null ? "the forecast" : forecastId + "'s forecast";
        if (x.warning() != null) {
            out.printf(Locale.ROOT, "watch WARNS%s at t=%.3f (line %d), rule %s: %s%n",
                    x.warning().property() == null ? "" : " of " + x.warning().property(), x.warning().time(),
                    x.warning().line(), x.rule().id(), x.warning().reason());
        } else if (x.rule() == WarningRule.FORECAST && r.forecast() != null) {
            if (outlived && last != null && last.novelSince() != null) {
                matching += ", which does not warn once the run is novel (line " + last.novelSince() + ")";
            }
            out.printf(Locale.ROOT, "watch does not warn of any property, rule forecast: %s peaked at %.2f before any "
                    + "violation, under the threshold %.2f; the thesis's matching: %s%n", about, r.forecast().peak(),
                    r.forecast().threshold(), matching);
        } else {
            out.println("watch does not warn of any property, rule " + x.rule().id() + ": " + matching);
        }
        if (r.noMatch()) {
            out.println("no model matches the whole run: it is unlike every learned scenario"
                    + (last != null && last.novelSince() != null ? "; the forecast went on, novel since line "
                    + last.novelSince() : " (no prediction)"));
        }
    }

    /**
     * Each other property's own forecast on the run, as the monitor told it: its peak before the property's violation
     * (or the run's end), or why the models gave it none ({@code no-abort: no forecast: never violated in 43 training
     * runs}).
     */
    private static void otherForecasts(PrintWriter out, RunResult r) {
        for (RunResult.PropertyResult p : r.properties()) {
            if (p.noForecast() != null) {
                out.println(p.property() + ": no forecast: " + p.noForecast());
            } else if (p.forecasts() != null && !p.forecasts().probabilities().isEmpty()) {
                boolean obligation = RunResult.PropertyResult.OBLIGATION.equals(p.scope());
                out.printf(Locale.ROOT, "%s's forecast: %s peaked at %.2f over %d forecast(s) before %s%n",
                        p.property(), obligation ? "P(miss)" : "P(violation)", p.forecasts().probabilities().stream()
                                .mapToDouble(x -> x).max().orElse(0), p.forecasts().probabilities().size(),
                        p.violation() == null ? "the run's end" : "its violation at t=" + String.format(Locale.ROOT,
                                "%.3f", p.violation()));
            }
        }
    }

    /** {@code explain --json}: the explanation with its forecasts as {@code watch --json} writes them. */
    record ExplanationJson(String log, List<StepJson> steps, List<Explanation.ModelFate> models, RunResult run,
                           String rule, String warning, OutcomeJson outcome) {

        static ExplanationJson of(Explanation x) {
            return new ExplanationJson(x.log(), x.steps().stream().map(s -> new StepJson(s.index(), s.time(),
                    s.line(), s.input(), s.output(), ForecastJson.of(s.forecast()))).toList(), x.models(), x.run(),
                    x.rule().id(), x.warning() == null ? null : x.warning().reason(), OutcomeJson.of(x.outcome()));
        }
    }

    /** One pair of {@code explain --json}, with the forecast right after it (null without one). */
    record StepJson(int index, double time, long line, String input, String output, ForecastJson forecast) {
    }
}
