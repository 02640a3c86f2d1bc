package dev.predmon.evaluate;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.LogWatcher;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Judges one log exactly as {@code watch --no-follow} would: the {@link LogWatcher} reads the file through the
 * parser into a {@link PredictiveMonitor} (built-in safety monitor included), and the events are collected
 * instead of printed.
 */
public final class Replay {

    private Replay() {
    }

    /**
     * Replays {@code log} against {@code models}.
     *
     * @param fold the fold it is tested in, or -1
     */
    public static RunResult run(Path log, String scenario, boolean faulty, int fold, ModelSet models,
                                Abstraction abstraction, int threshold) throws IOException {
        List<MonitorEvent> events = new ArrayList<>();
        int[] problems = {0};
        PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, threshold, events::add);
        try (LogWatcher watcher = new LogWatcher(log, monitor, p -> problems[0]++)) {
            watcher.drain();
        }
        MonitorEvent.Warning warning = null;
        MonitorEvent.Violation violation = null;
        MonitorEvent.NoMatch noMatch = null;
        List<RunResult.Elimination> eliminations = new ArrayList<>();
        for (MonitorEvent e : events) {
            if (e instanceof MonitorEvent.Warning w && warning == null) {
                warning = w;
            } else if (e instanceof MonitorEvent.Violation v && violation == null) {
                violation = v;
            } else if (e instanceof MonitorEvent.NoMatch n && noMatch == null) {
                noMatch = n;
            } else if (e instanceof MonitorEvent.Eliminated x) {
                eliminations.add(new RunResult.Elimination(x.model(), x.scenario(), x.faulty(), x.time(), x.line(),
                        x.reason()));
            }
        }
        Double warningTime = warning == null ? null : warning.time();
        Double violationTime = violation == null ? null : violation.time();
        Verdict verdict = Verdict.of(faulty, warningTime, violationTime);
        Double lead = verdict == Verdict.WARNED_BEFORE_VIOLATION ? violationTime - warningTime : null;
        return new RunResult(scenario, faulty, log.toString(), fold, verdict, warningTime,
                warning == null ? null : warning.line(), warning == null ? List.of() : warning.scenarios(),
                warning == null ? null : warning.battery(), violationTime, lead, noMatch != null,
                noMatch == null ? null : noMatch.time(), monitor.pipeline().records(), monitor.pairs(), problems[0],
                List.copyOf(eliminations), monitor.battery() != null);
    }
}
