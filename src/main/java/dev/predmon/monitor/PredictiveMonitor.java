package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.SafetyRule;
import dev.predmon.compact.IoPair;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.LogRecord;
import dev.predmon.pipeline.PipelineListener;
import dev.predmon.pipeline.TracePipeline;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.TreeSet;
import java.util.function.Consumer;

/**
 * The predictive monitor: the thesis's Algorithm 8 with MatchTracesRT, made incremental. Records are pushed
 * one at a time through the shared {@link TracePipeline}; each compacted pair advances every model still alive
 * by its two Mealy steps ({@code input/OK}, {@code Delta/output}); a model is dropped at an input it cannot take
 * or when its discrepancies exceed the threshold. A warning is raised as soon as every nominal scenario is
 * eliminated while a faulty one still matches. A scenario matches while any of its machines matches.
 *
 * <p>Per record the work is constant (one step per model) and the state is constant (per model: state,
 * discrepancy count, alive), so the monitor never re-reads the log, unlike the thesis's loop.
 *
 * <p>The built-in safety monitor (the property of the abstraction file, by default {@code level < 20.0} on the
 * BatteryReader channel) runs alongside on the raw records and reports the first violation, so that the lead
 * of the warning over the violation can be seen.
 */
public final class PredictiveMonitor implements PipelineListener {

    private final List<ModelTracker> trackers = new ArrayList<>();
    private final Optional<SafetyRule> safety;
    private final Consumer<MonitorEvent> events;
    private final TracePipeline pipeline;
    private MonitorEvent.Warning warning;
    private MonitorEvent.Violation violation;
    private boolean noMatch;
    private Double battery;
    private long pairs;

    /**
     * @param threshold discrepancies a model may accumulate and still match (0: exact matching)
     * @param events    receives every event, in log order
     */
    public PredictiveMonitor(ModelSet models, Abstraction abstraction, int threshold, Consumer<MonitorEvent> events) {
        for (LearnedModel m : models.models()) {
            trackers.add(new ModelTracker(m, threshold));
        }
        this.safety = abstraction.safety();
        this.events = events;
        this.pipeline = new TracePipeline(abstraction, this);
    }

    /** Takes the next record of the log. */
    public void accept(LogRecord record) {
        pipeline.accept(record);
    }

    /** The log is complete (batch or {@code --no-follow}): pairs still pending are matched. */
    public void endOfInput() {
        pipeline.endOfInput();
    }

    /** The log was truncated or replaced: start over as for a new run. */
    public void restart(String reason) {
        pipeline.reset();
        trackers.forEach(ModelTracker::reset);
        warning = null;
        violation = null;
        noMatch = false;
        battery = null;
        pairs = 0;
        events.accept(new MonitorEvent.Restarted(reason));
    }

    @Override
    public void record(LogRecord record) {
        if (safety.isEmpty()) {
            return;
        }
        double v = safety.get().valueOf(record);
        if (Double.isNaN(v)) {
            return;
        }
        battery = v;
        if (violation == null && safety.get().violatedBy(v)) {
            violation = new MonitorEvent.Violation(record.time(), record.line(), safety.get().name(), v);
            events.accept(violation);
        }
    }

    @Override
    public void unmapped(String key, LogRecord record) {
        events.accept(new MonitorEvent.Unmapped(record.time(), record.line(), key));
    }

    @Override
    public void pair(IoPair pair, LogRecord trigger) {
        pairs++;
        for (ModelTracker t : trackers) {
            if (!t.alive()) {
                continue;
            }
            if (!t.pair(pair.input(), pair.output())) {
                LearnedModel m = t.model();
                events.accept(new MonitorEvent.Eliminated(trigger.time(), trigger.line(), m.id(), m.scenario(),
                        m.faulty(), t.elimination().describe()));
            }
        }
        TreeSet<String> faultyAlive = new TreeSet<>();
        boolean nominalAlive = false;
        for (ModelTracker t : trackers) {
            if (t.alive()) {
                if (t.model().faulty()) {
                    faultyAlive.add(t.model().scenario());
                } else {
                    nominalAlive = true;
                }
            }
        }
        if (warning == null && !nominalAlive && !faultyAlive.isEmpty()) {
            warning = new MonitorEvent.Warning(trigger.time(), trigger.line(), List.copyOf(faultyAlive), battery, pairs);
            events.accept(warning);
        }
        if (!noMatch && !nominalAlive && faultyAlive.isEmpty()) {
            noMatch = true;
            events.accept(new MonitorEvent.NoMatch(trigger.time(), trigger.line()));
        }
    }

    /** The warning, once raised. */
    public Optional<MonitorEvent.Warning> warning() {
        return Optional.ofNullable(warning);
    }

    /** The safety violation, once seen. */
    public Optional<MonitorEvent.Violation> violation() {
        return Optional.ofNullable(violation);
    }

    /** Whether a point came where no model, nominal or faulty, matched the run any more (since the last restart). */
    public boolean noMatch() {
        return noMatch;
    }

    /** Every model's tracker, in model order. */
    public List<ModelTracker> trackers() {
        return List.copyOf(trackers);
    }

    /** Last value on the safety property's channel (the battery level), or null. */
    public Double battery() {
        return battery;
    }

    /** Compacted pairs matched so far. */
    public long pairs() {
        return pairs;
    }

    /** The pipeline's counters (records, interface records, unmapped messages). */
    public TracePipeline pipeline() {
        return pipeline;
    }
}
