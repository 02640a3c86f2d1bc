package dev.predmon.evaluate;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.EventModel;
import dev.predmon.forecast.ThresholdChoice;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.monitor.WarningRule;
import dev.predmon.pipeline.RunId;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.property.Absence;
import dev.predmon.property.Precedence;
import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker;
import dev.predmon.replay.LogReplay;
import dev.predmon.replay.ReplayedLog;
import dev.predmon.replay.ReplayedRun;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Judges one log exactly as {@code watch --no-follow} would, run by run, from the one replay of it ({@link
 * LogReplay}): the verdict, the lead, the forecasts before the violation and the raw-value baseline of each run.
 */
public final class Replay {

    private Replay() {
    }

    /**
     * Replays {@code log} against {@code models}: one result per run the log holds, of the runs {@code label}
     * selects (each judged by its own warning and violation).
     *
     * @param fold the fold it is tested in, or -1
     */
    public static List<RunResult> run(Path log, String scenario, boolean faulty, RunLabel label, int fold,
                                      ModelSet models, Abstraction abstraction, int tolerance, int confirm)
            throws IOException {
        return run(log, scenario, faulty, label, fold, models, abstraction, tolerance, confirm,
                PredictiveMonitor.defaultRule(models));
    }

    /** As above, warning by {@code rule}. */
    public static List<RunResult> run(Path log, String scenario, boolean faulty, RunLabel label, int fold,
                                      ModelSet models, Abstraction abstraction, int tolerance, int confirm,
                                      WarningRule rule) throws IOException {
        return run(log, scenario, faulty, label, fold, models, abstraction, tolerance, confirm, rule, Map.of());
    }

    /**
     * As above, with the base rate of each property other than the forecast's: the share of the training runs of
     * {@code models} that violated it (what a value forecast of it is scored against; a deadline's comes from the
     * models' obligations).
     */
    public static List<RunResult> run(Path log, String scenario, boolean faulty, RunLabel label, int fold,
                                      ModelSet models, Abstraction abstraction, int tolerance, int confirm,
                                      WarningRule rule, Map<String, Double> baseRates) throws IOException {
        Approaches approaches = Approaches.of(models, abstraction);
        ReplayedLog replayed = LogReplay.replay(log, models, abstraction, tolerance, confirm, rule,
                approaches::record);
        return of(replayed, scenario, faulty, label, fold, models, abstraction, approaches, baseRates);
    }

    /**
     * As above, from the one replay of the log ({@link LogReplay}), {@code approaches} having taken its records: each
     * run's verdict, its forecasts before the violation with their times, its eliminations and its other properties
     * come from that replay's stream.
     */
    public static List<RunResult> of(ReplayedLog replayed, String scenario, boolean faulty, RunLabel label, int fold,
                                     ModelSet models, Abstraction abstraction, Approaches approaches) {
        return of(replayed, scenario, faulty, label, fold, models, abstraction, approaches, Map.of());
    }

    /**
     * As above, with the base rates of the other properties' value forecasts by property id. When the raw-value
     * baseline of a bound warned ({@link Approach#belowFloor}) is the run's {@code beyond} for that property, as the
     * elapsed-time baseline's is for a deadline.
     */
    public static List<RunResult> of(ReplayedLog replayed, String scenario, boolean faulty, RunLabel label, int fold,
                                     ModelSet models, Abstraction abstraction, Approaches approaches,
                                     Map<String, Double> baseRates) {
        Approach approach = approaches.of(abstraction.safety().map(Property::id).orElse(null));
        List<ReplayedRun> runs = replayed.runs();
        List<RunResult> results = new ArrayList<>();
        for (ReplayedRun r : runs) {
            RunOutcome o = r.outcome();
            if (!label.selects(o.violation() != null)) {
                continue;
            }
            List<RunResult.Elimination> eliminations = new ArrayList<>();
            MonitorEvent.NoMatch noMatch = null;
            Map<String, Double> warnings = new HashMap<>();
            Map<String, Double> violations = new HashMap<>();
            Map<String, Double> beyond = new HashMap<>();
            for (MonitorEvent e : r.events()) {
                if (e instanceof MonitorEvent.Eliminated x) {
                    eliminations.add(new RunResult.Elimination(x.model(), x.scenario(), x.faulty(), x.time(), x.line(),
                            x.reason()));
                } else if (e instanceof MonitorEvent.NoMatch n && noMatch == null) {
                    noMatch = n;
                } else if (e instanceof MonitorEvent.Warning w && w.property() != null) {
                    warnings.putIfAbsent(w.property(), w.time());
                } else if (e instanceof MonitorEvent.Violation v) {
                    violations.putIfAbsent(v.property(), v.time());
                } else if (e instanceof MonitorEvent.ForecastChanged c && c.deadline() != null && c.deadline().novel()) {
                    beyond.putIfAbsent(c.property(), c.time());
                }
            }
            approaches.all().forEach((id, a) -> {
                Double at = a.belowFloor(o.run());
                if (at != null) {
                    beyond.put(id, at);
                }
            });
            MonitorEvent.Warning warning = o.warning();
            MonitorEvent.Violation violation = o.violation();
            Double warningTime = warning == null ? null : warning.time();
            Double violationTime = violation == null ? null : violation.time();
            Verdict verdict = Verdict.of(faulty, warningTime, violationTime);
            Double lead = verdict == Verdict.WARNED_BEFORE_VIOLATION ? violationTime - warningTime : null;
            List<ReplayedRun.Timed> scored = r.beforeViolation();
            results.add(new RunResult(scenario, faulty, RunId.of(replayed.log(), o.run(), runs.size()), fold,
                    verdict, warningTime, warning == null ? null : warning.line(),
                    warning == null ? List.of() : warning.scenarios(), warning == null ? null : warning.value(),
                    violationTime, lead, noMatch != null, noMatch == null ? null : noMatch.time(),
                    runs.size() == 1 ? replayed.records() : -1, o.pairs(), replayed.problems().size(),
                    List.copyOf(eliminations), o.safetyObserved(), replayed.unit(),
                    violation != null && approach.near(o.run()) < RunResult.SUDDEN_READINGS, approaches.start(o.run()),
                    approach.near(o.run()), violation == null ? null : violation.before(),
                    models.forecast() == null ? null : new RunResult.ForecastTrace(
                            scored.stream().map(t -> t.forecast().probability()).toList(), o.forecast(),
                            warning == null ? null : warning.forecast(), models.forecast().baseRate(),
                            models.forecast().threshold(), approach.belowFloor(o.run()),
                            scored.stream().map(ReplayedRun.Timed::time).toList()),
                    others(abstraction, o.properties(), warnings, baseRateWarnings(abstraction, beyond, baseRates,
                            approaches.start(o.run())), violations, PropertyForecasts.of(r.events(), abstraction,
                            models.forecast(), baseRates), models)));
        }
        return results;
    }

    /**
     * {@code beyond} with the base rate's warning of every absence and precedence: at the run's {@code start} where its
     * training runs violated it at even odds or more ({@link ThresholdChoice#DEFAULT}), never where they did not.
     */
    private static Map<String, Double> baseRateWarnings(Abstraction abstraction, Map<String, Double> beyond,
                                                        Map<String, Double> baseRates, double start) {
        for (Property p : abstraction.properties()) {
            Double rate = baseRates.get(p.id());
            if ((p instanceof Absence || p instanceof Precedence) && rate != null && rate >= ThresholdChoice.DEFAULT) {
                beyond.putIfAbsent(p.id(), start);
            }
        }
        return beyond;
    }

    /** Every property but the forecast's, with its first warning and violation in the run and its forecasts. */
    private static List<RunResult.PropertyResult> others(Abstraction abstraction,
                                                         List<PropertyChecker.PropertyVerdict> verdicts,
                                                         Map<String, Double> warnings, Map<String, Double> beyond,
                                                         Map<String, Double> violations,
                                                         Map<String, PropertyForecasts> forecasts, ModelSet models) {
        String forecast = abstraction.safety().map(Property::id).orElse(null);
        List<RunResult.PropertyResult> out = new ArrayList<>();
        Map<String, dev.predmon.property.Verdict> verdict = new HashMap<>(); // not evaluate's Verdict
        verdicts.forEach(pv -> verdict.put(pv.property().id(), pv.verdict()));
        for (Property p : abstraction.properties()) {
            if (!p.id().equals(forecast)) {
                PropertyForecasts f = forecasts.get(p.id());
                dev.predmon.property.Verdict v = verdict.get(p.id());
                EventModel e = models.forecast() == null ? null : models.forecast().events().get(p.id());
                out.add(new RunResult.PropertyResult(p.id(), warnings.get(p.id()), violations.get(p.id()),
                        beyond.get(p.id()), f == null ? null : f.run(), f == null ? null : f.scope(),
                        v == null ? null : v.id(), v == null ? null : v.describe(), e == null ? null : e.why()));
            }
        }
        return out;
    }
}
