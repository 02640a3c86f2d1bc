package dev.predmon.replay;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.compact.IoPair;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.Survival;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.DeadlineSteps;
import dev.predmon.monitor.LogWatcher;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.monitor.WarningRule;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;
import dev.predmon.pipeline.PipelineListener;
import dev.predmon.property.Response;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Replays one complete log exactly as {@code watch --no-follow} judges it: the {@link LogWatcher} reads the file
 * through the parser into a {@link PredictiveMonitor} (built-in safety monitor included), and what the monitor makes
 * of it is kept per run instead of printed: its pairs and gaps (seen through {@link PredictiveMonitor#tee}), every
 * forecast with the record that made it ({@link PredictiveMonitor#onEveryForecast}), every deadline forecast of each
 * obligation with how it ended ({@link PredictiveMonitor#onEveryDeadlineForecast}), and its events.
 */
public final class LogReplay {

    private LogReplay() {
    }

    /** What a replay keeps of each run beside its events, pairs and gaps. */
    public enum Detail {
        /** Every forecast, bound forecast and deadline forecast with its record: what learn, evaluate and explain read. */
        FORECASTS,
        /**
         * The events, pairs and gaps only: what a verdict and the matching read ({@code classify}). The monitor judges
         * exactly as with {@link #FORECASTS}; only what is kept differs, so a long log's replay stays small.
         */
        VERDICTS
    }

    /**
     * Replays {@code log} against {@code models}, warning by {@code rule}.
     *
     * @param tolerance discrepancies a model may accumulate and still match
     * @param confirm   pairs a faulty model must match after the last nominal one is eliminated
     * @param taken     gets every record with its run right after the monitor took it
     */
    public static ReplayedLog replay(Path log, ModelSet models, Abstraction abstraction, int tolerance, int confirm,
                                     WarningRule rule, RecordTaken taken) throws IOException {
        return replay(log, models, abstraction, tolerance, confirm, rule, taken, Detail.FORECASTS);
    }

    /** As above, keeping {@code detail} of each run. */
    public static ReplayedLog replay(Path log, ModelSet models, Abstraction abstraction, int tolerance, int confirm,
                                     WarningRule rule, RecordTaken taken, Detail detail)
            throws IOException {
        List<Builder> runs = new ArrayList<>();
        PredictiveMonitor[] self = new PredictiveMonitor[1];
        LogRecord[] current = new LogRecord[1];
        PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, tolerance, confirm, rule,
                e -> of(runs, self[0].run()).event(e));
        self[0] = monitor;
        monitor.tee(new PipelineListener() {
            @Override
            public void runStarted(int number, LogRecord first) {
                of(runs, monitor.run()).end(monitor); // before the monitor starts the next run over
            }

            @Override
            public void record(LogRecord record) {
                current[0] = record;
            }

            @Override
            public void gap(LogRecord record) {
                current[0] = record;
                of(runs, monitor.run()).gaps.add(record.line());
            }

            @Override
            public void pair(IoPair pair, LogRecord trigger) {
                current[0] = trigger;
                of(runs, monitor.run()).pairs.add(new ReplayedRun.Pair(pair, trigger.time(), trigger.line()));
            }
        });
        if (detail == Detail.FORECASTS) {
            keepForecasts(monitor, runs, current);
        }
        List<ParseProblem> problems = new ArrayList<>();
        long lines;
        try (LogWatcher watcher = LogWatcher.withRecords(log, monitor, problems::add,
                r -> taken.taken(r, monitor.run(), monitor.judged()))) {
            watcher.drain();
            lines = watcher.lines();
        }
        of(runs, monitor.run()).end(monitor);
        List<ReplayedRun> out = new ArrayList<>();
        for (RunOutcome o : monitor.runs()) {
            Builder b = of(runs, o.run());
            out.add(new ReplayedRun(o.run(), o, b.pairs, b.gaps, b.forecasts,
                    b.violatedAfter < 0 ? b.forecasts.size() : b.violatedAfter, b.events, b.models, b.matchRuleAt,
                    b.obligations, b.bounds, b.boundsBefore));
        }
        return new ReplayedLog(log, out, problems, lines, monitor);
    }

    /** As above, with the models' default rule ({@link PredictiveMonitor#defaultRule}) and no record hook. */
    public static ReplayedLog replay(Path log, ModelSet models, Abstraction abstraction, int tolerance, int confirm)
            throws IOException {
        return replay(log, models, abstraction, tolerance, confirm, PredictiveMonitor.defaultRule(models),
                (r, run, judged) -> { });
    }

    /** Keeps every forecast of {@code monitor}, of the forecast's property, every bound and every deadline. */
    private static void keepForecasts(PredictiveMonitor monitor, List<Builder> runs, LogRecord[] current) {
        monitor.onEveryDeadlineForecast(new DeadlineSteps() {
            @Override
            public void forecast(int run, Response property, LogRecord record, double elapsed,
                                 Survival.Estimate raw, Survival curve) {
                Pending p = of(runs, run).pending.computeIfAbsent(property.id(), id -> new Pending());
                p.steps.add(new ReplayedRun.Step(raw, elapsed, record.time(), record.line()));
                p.curve = curve;
            }

            @Override
            public void ended(int run, Response property, LogRecord record, double duration, boolean discharged) {
                Pending p = of(runs, run).pending.remove(property.id());
                of(runs, run).obligations.add(new ReplayedRun.Obligation(property,
                        p == null ? List.of() : p.steps, duration, discharged, record.time(), record.line(),
                        p == null ? Double.NaN : p.warnedAt, p == null ? null : p.curve));
            }
        });
        monitor.onEveryForecast((Forecast f, int run) -> of(runs, run).forecasts.add(new ReplayedRun.Timed(f,
                current[0].time(), current[0].line(), monitor.pairs())));
        monitor.onEveryBoundForecast((String property, Forecast f, int run) -> of(runs, run).bound(property, new ReplayedRun.Timed(f,
                current[0].time(), current[0].line(), monitor.pairs())));
    }

    private static Builder of(List<Builder> runs, int run) {
        while (runs.size() <= run) {
            runs.add(new Builder());
        }
        return runs.get(run);
    }

    /** One run's stream while it is replayed. */
    private static final class Builder {
        final List<ReplayedRun.Pair> pairs = new ArrayList<>();
        final List<Long> gaps = new ArrayList<>();
        final List<ReplayedRun.Timed> forecasts = new ArrayList<>();
        final List<MonitorEvent> events = new ArrayList<>();
        /** Forecasts made before the forecast property's first violation, or -1 while it holds. */
        int violatedAfter = -1;
        List<ReplayedRun.Fate> models = List.of();
        long matchRuleAt = -1;
        final List<ReplayedRun.Obligation> obligations = new ArrayList<>();
        /** By property id, the deadline forecasts of its obligation pending now. */
        final Map<String, Pending> pending = new HashMap<>();
        /** By bound property id, its forecasts; and how many came before its first violation, once it came. */
        final Map<String, List<ReplayedRun.Timed>> bounds = new TreeMap<>();
        final Map<String, Integer> boundsBefore = new TreeMap<>();

        void bound(String property, ReplayedRun.Timed t) {
            bounds.computeIfAbsent(property, k -> new ArrayList<>()).add(t);
        }

        /** The run ends: how the matching left each model. */
        void end(PredictiveMonitor monitor) {
            models = monitor.trackers().stream().map(ReplayedRun.Fate::of).toList();
            matchRuleAt = monitor.matchRuleAt();
        }

        void event(MonitorEvent e) {
            events.add(e);
            if (e instanceof MonitorEvent.Violation v && v.property() != null) {
                boundsBefore.putIfAbsent(v.property(), bounds.getOrDefault(v.property(), List.of()).size());
            }
            if (e instanceof MonitorEvent.Violation v && v.forecast() && violatedAfter < 0) {
                violatedAfter = forecasts.size();
            }
            if (e instanceof MonitorEvent.Warning w && w.clause() == MonitorEvent.Clause.DEADLINE) {
                Pending p = pending.get(w.property());
                if (p != null && !p.steps.isEmpty()) {
                    p.warnedAt = p.steps.get(p.steps.size() - 1).elapsed(); // told right after the forecast that warned
                }
            }
        }
    }

    /** One pending obligation's deadline forecasts so far, and when its warning came. */
    private static final class Pending {
        final List<ReplayedRun.Step> steps = new ArrayList<>();
        double warnedAt = Double.NaN;
        /** The curve it is judged against. */
        Survival curve;
    }
}
