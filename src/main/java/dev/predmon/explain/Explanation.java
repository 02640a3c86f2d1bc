package dev.predmon.explain;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.compact.IoPair;
import dev.predmon.evaluate.Approaches;
import dev.predmon.evaluate.Replay;
import dev.predmon.evaluate.RunResult;
import dev.predmon.forecast.Forecast;
import dev.predmon.matching.ModelTracker;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.PropertyOutcome;
import dev.predmon.monitor.WarningRule;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.replay.LogReplay;
import dev.predmon.replay.ReplayedLog;
import dev.predmon.replay.ReplayedRun;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Why {@code watch} warned or did not: the run's abstract trace pair by pair and, for each model, where it stopped
 * matching and why (the symbol it expected versus the one seen). Everything is read off one replay of the log
 * through {@code watch}'s monitor ({@link LogReplay}): the pairs, the forecasts, how its matching left each model,
 * the warning and the verdict, so the explanation and the monitor cannot disagree.
 *
 * @param log    the run
 * @param steps  the compacted trace, one query/reply pair each
 * @param models every model's fate, in model order
 * @param run    the monitor's verdict on the run (scenario unknown: judged as nominal)
 * @param rule   the rule the monitor warned by
 * @param warning the run's first warning of any property as the monitor raised it, with its reason, or null
 * @param matchRuleAt the pair after which the thesis's match rule held ({@code confirm} included), warning or not, or
 *                    -1
 * @param outcome every property's outcome on the run, worst first ({@link PropertyOutcome#of})
 */
public record Explanation(String log, List<Step> steps, List<ModelFate> models, RunResult run, WarningRule rule,
                          MonitorEvent.Warning warning, long matchRuleAt, List<PropertyOutcome> outcome) {

    /**
     * One compacted pair.
     *
     * @param index  0-based pair index (Mealy steps {@code 2*index} and {@code 2*index+1})
     * @param time   time of the record that completed it
     * @param line   that record's line
     * @param input    input symbol (the command)
     * @param output   output symbol (the reply)
     * @param forecast the monitor's forecast right after it, or null when the models carry none
     */
    public record Step(int index, double time, long line, String input, String output, Forecast forecast) {
    }

    /**
     * What became of one model.
     *
     * @param model          its id
     * @param scenario       its scenario
     * @param faulty         whether that scenario is faulty
     * @param matched        it matched the whole trace (within the tolerance)
     * @param stoppedAt      the pair at which it was eliminated, or null
     * @param input          the input there
     * @param expected       the output it expected, or null when it had no transition for the input
     * @param seen           the output seen
     * @param discrepancies  outputs that differed up to its elimination or the end
     * @param reason         one line for users
     */
    public record ModelFate(String model, String scenario, boolean faulty, boolean matched, Integer stoppedAt,
                            String input, String expected, String seen, int discrepancies, String reason) {
    }

    /**
     * Explains {@code log} against {@code models}: one explanation per run the log holds, from one replay of it
     * ({@link LogReplay}) with the models' default rule.
     */
    public static List<Explanation> of(Path log, ModelSet models, Abstraction abstraction, int tolerance, int confirm)
            throws IOException {
        Approaches approaches = Approaches.of(models, abstraction);
        return of(LogReplay.replay(log, models, abstraction, tolerance, confirm, PredictiveMonitor.defaultRule(models),
                approaches::record), models, abstraction, approaches);
    }

    /** Explains a log already replayed, {@code approaches} ({@link Approaches#of}) having taken its records. */
    public static List<Explanation> of(ReplayedLog replayed, ModelSet models, Abstraction abstraction,
                                       Approaches approaches) {
        WarningRule rule = replayed.monitor().rule();
        List<RunResult> verdicts = Replay.of(replayed, "?", false, RunLabel.ALL, -1, models, abstraction, approaches);
        List<Explanation> all = new ArrayList<>();
        for (int i = 0; i < replayed.runs().size(); i++) {
            all.add(of(replayed.runs().get(i), verdicts.get(i), rule,
                    replayed.monitor().forecastProperty().orElse(null)));
        }
        return List.copyOf(all);
    }

    private static Explanation of(ReplayedRun replayed, RunResult run, WarningRule rule, String forecastId) {
        List<Forecast> forecasts = replayed.afterPairs();
        List<Step> steps = new ArrayList<>();
        for (int i = 0; i < replayed.pairs().size(); i++) {
            IoPair p = replayed.pairs().get(i).pair();
            steps.add(new Step(i, p.reply().time(), p.reply().line(), p.input(), p.output(),
                    i < forecasts.size() ? forecasts.get(i) : null));
        }
        List<ModelFate> fates = new ArrayList<>();
        for (ReplayedRun.Fate t : replayed.models()) {
            LearnedModel m = t.model();
            ModelTracker.Failure f = t.elimination();
            if (f == null) {
                fates.add(new ModelFate(m.id(), m.scenario(), m.faulty(), true, null, null, null, null,
                        t.discrepancies(), t.discrepancies() == 0 ? "matches the whole run"
                        : "matches the whole run with " + t.discrepancies() + " discrepancy(ies), first: "
                        + t.firstDiscrepancy().describe()));
            } else {
                int pair = MealyMapping.pairOfStep(f.step());
                // A pair's command step is input/OK, its reply step Delta/reply: name the real symbols.
                boolean command = MealyMapping.isCommandStep(f.step());
                String input = command ? f.input() : steps.get(pair).input();
                String reason = f.expected() == null
                        ? (command ? "no transition for command " + input
                        : "no transition for the reply to " + input)
                        : "after command " + input + " expected reply " + f.expected() + " but saw " + f.seen();
                fates.add(new ModelFate(m.id(), m.scenario(), m.faulty(), false, pair, input, f.expected(), f.seen(),
                        t.discrepancies(), reason));
            }
        }
        return new Explanation(run.log().name(), List.copyOf(steps), List.copyOf(fates), run, rule,
                replayed.outcome().firstWarning(), replayed.matchRuleAt(),
                PropertyOutcome.of(replayed.outcome(), forecastId));
    }
}
