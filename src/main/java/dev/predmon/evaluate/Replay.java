package dev.predmon.evaluate;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.Forecast;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.LogWatcher;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.LogRecord;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Judges one log exactly as {@code watch --no-follow} would: the {@link LogWatcher} reads the file through the
 * parser into a {@link PredictiveMonitor} (built-in safety monitor included), and the events are collected
 * instead of printed.
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
                                      ModelSet models, Abstraction abstraction, int threshold, int confirm)
            throws IOException {
        return run(log, scenario, faulty, label, fold, models, abstraction, threshold, confirm,
                PredictiveMonitor.defaultRule(models));
    }

    /** As above, warning by {@code rule}. */
    public static List<RunResult> run(Path log, String scenario, boolean faulty, RunLabel label, int fold,
                                      ModelSet models, Abstraction abstraction, int threshold, int confirm,
                                      WarningRule rule) throws IOException {
        return run(log, scenario, faulty, label, fold, models, abstraction, threshold, confirm, rule, Trail.NONE);
    }

    /** As above, also telling {@code trail} the forecast after each pair and the warnings as raised. */
    public static List<RunResult> run(Path log, String scenario, boolean faulty, RunLabel label, int fold,
                                      ModelSet models, Abstraction abstraction, int threshold, int confirm,
                                      WarningRule rule, Trail trail) throws IOException {
        List<MonitorEvent> events = new ArrayList<>();
        int[] problems = {0};
        PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, threshold, confirm, rule, events::add);
        Map<Integer, List<Double>> probabilities = new HashMap<>();
        Map<Integer, List<Double>> times = new HashMap<>();
        Set<Integer> violated = new HashSet<>();
        // Forecasts are made while the monitor takes a record: each gets that record's time once it is taken.
        List<List<Double>> untimed = new ArrayList<>();
        double[] lastTime = {0};
        monitor.onEveryForecast((f, run) -> {
            trail.forecast(run, monitor.pairs(), f);
            if (!violated.contains(run) && f.basis() != Forecast.Basis.VIOLATED) {
                probabilities.computeIfAbsent(run, r -> new ArrayList<>()).add(f.probability());
                List<Double> ts = times.computeIfAbsent(run, r -> new ArrayList<>());
                ts.add(Double.NaN);
                untimed.add(ts);
            } else {
                violated.add(run);
            }
        });
        Approach approach = new Approach(abstraction.safety().orElse(null), monitor,
                models.forecast() == null ? Double.NaN : models.forecast().lows().safeFloor());
        try (LogWatcher watcher = LogWatcher.withRecords(log, monitor, p -> problems[0]++, r -> {
            lastTime[0] = r.time();
            timed(untimed, r.time());
            approach.record(r);
        })) {
            watcher.drain();
        }
        timed(untimed, lastTime[0]); // what the end of the input flushed
        List<RunOutcome> runs = monitor.runs();
        List<RunResult> results = new ArrayList<>();
        for (RunOutcome o : runs) {
            if (!label.selects(o.violation() != null)) {
                continue;
            }
            List<RunResult.Elimination> eliminations = new ArrayList<>();
            MonitorEvent.NoMatch noMatch = null;
            for (MonitorEvent e : events) {
                if (e instanceof MonitorEvent.Eliminated x && x.run() == o.run()) {
                    eliminations.add(new RunResult.Elimination(x.model(), x.scenario(), x.faulty(), x.time(), x.line(),
                            x.reason()));
                } else if (e instanceof MonitorEvent.NoMatch n && n.run() == o.run() && noMatch == null) {
                    noMatch = n;
                }
            }
            MonitorEvent.Warning warning = o.warning();
            trail.warning(o.run(), warning);
            MonitorEvent.Violation violation = o.violation();
            Double warningTime = warning == null ? null : warning.time();
            Double violationTime = violation == null ? null : violation.time();
            Verdict verdict = Verdict.of(faulty, warningTime, violationTime);
            Double lead = verdict == Verdict.WARNED_BEFORE_VIOLATION ? violationTime - warningTime : null;
            results.add(new RunResult(scenario, faulty, LogTrace.name(log, o.run(), runs.size()), fold, verdict,
                    warningTime, warning == null ? null : warning.line(),
                    warning == null ? List.of() : warning.scenarios(), warning == null ? null : warning.battery(),
                    violationTime, lead, noMatch != null, noMatch == null ? null : noMatch.time(),
                    runs.size() == 1 ? monitor.pipeline().records() : -1, o.pairs(), problems[0],
                    List.copyOf(eliminations), o.safetyObserved(), monitor.clock().unit(),
                    violation != null && approach.near(o.run()) < RunResult.SUDDEN_READINGS, approach.start(o.run()),
                    approach.near(o.run()), violation == null ? null : violation.before(),
                    models.forecast() == null ? null : new RunResult.ForecastTrace(
                            List.copyOf(probabilities.getOrDefault(o.run(), List.of())), o.forecast(),
                            warning == null ? null : warning.forecast(), models.forecast().baseRate(),
                            models.forecast().threshold(), approach.belowFloor(o.run()),
                            times.getOrDefault(o.run(), List.of())),
                    others(abstraction, events, o.run())));
        }
        return results;
    }

    /** Gives the forecasts that wait for their time {@code time}. */
    private static void timed(List<List<Double>> untimed, double time) {
        for (List<Double> ts : untimed) {
            for (int i = ts.size() - 1; i >= 0 && Double.isNaN(ts.get(i)); i--) {
                ts.set(i, time);
            }
        }
        untimed.clear();
    }

    /** Every property but the forecast's, with its first warning and violation in run {@code run}. */
    private static List<RunResult.PropertyResult> others(Abstraction abstraction, List<MonitorEvent> events, int run) {
        String forecast = abstraction.safety().map(Property::id).orElse(null);
        List<RunResult.PropertyResult> out = new ArrayList<>();
        for (Property p : abstraction.properties()) {
            if (p.id().equals(forecast)) {
                continue;
            }
            Double warning = null;
            Double violation = null;
            for (MonitorEvent e : events) {
                if (e instanceof MonitorEvent.Warning w && w.run() == run && p.id().equals(w.property())
                        && warning == null) {
                    warning = w.time();
                } else if (e instanceof MonitorEvent.Violation v && v.run() == run && p.id().equals(v.property())
                        && violation == null) {
                    violation = v.time();
                }
            }
            out.add(new RunResult.PropertyResult(p.id(), warning, violation));
        }
        return out;
    }

    /**
     * Per run, the time of its first record and the readings near the bound on the way to its violation (since the
     * value was last above the band), seen after the
     * monitor took each record (so that {@link PredictiveMonitor#run()} already counts a record that starts a run).
     * Read with the safety monitor's own {@link Bound#valueOf}, so the violation counted up to is the one it
     * reported.
     */
    private static final class Approach {
        private final Bound rule;
        private final PredictiveMonitor monitor;
        /** The lowest value a safe training run read: the raw-value baseline warns below it (NaN: never). */
        private final double floor;
        /** Per run, when the value first went below the floor, and when the current stretch below it began. */
        private final Map<Integer, Double> firstBelow = new HashMap<>();
        private final Map<Integer, Double> below = new HashMap<>();
        private final Map<Integer, Double> belowAtViolation = new HashMap<>();
        private final Map<Integer, Double> start = new HashMap<>();
        private final Map<Integer, Integer> near = new HashMap<>();
        private final Set<Integer> violated = new HashSet<>();

        Approach(Bound rule, PredictiveMonitor monitor, double floor) {
            this.rule = rule;
            this.monitor = monitor;
            this.floor = floor;
        }

        void record(LogRecord r) {
            int run = monitor.run();
            start.putIfAbsent(run, r.time());
            if (rule == null || violated.contains(run)) {
                return;
            }
            double v = rule.valueOf(r);
            if (Double.isNaN(v)) {
                return;
            }
            if (rule.violatedBy(v)) {
                violated.add(run);
                Double stretch = below.get(run);
                if (stretch != null) {
                    belowAtViolation.put(run, stretch);
                }
                return;
            }
            if (v < floor) {
                firstBelow.putIfAbsent(run, r.time());
                below.putIfAbsent(run, r.time());
            } else {
                below.remove(run); // the baseline's alarm ends when its cause ends, as the monitor's do
            }
            if (v < rule.floor() + RunResult.APPROACH_BAND) {
                near.merge(run, 1, Integer::sum);
            } else {
                // Back above the band: an earlier dip that recovered (a recharge) is no approach to a later violation.
                near.remove(run);
            }
        }

        double start(int run) {
            return start.getOrDefault(run, 0.0);
        }

        /**
         * When the raw-value baseline warned run {@code run}, or null: for a violated run, the start of the stretch
         * below the floor that lasted until the violation (a dip that recovered earlier does not foresee it); for a
         * run that held, its first stretch (a false alarm).
         */
        Double belowFloor(int run) {
            return violated.contains(run) ? belowAtViolation.get(run) : firstBelow.get(run);
        }

        int near(int run) {
            return near.getOrDefault(run, 0);
        }
    }
}
