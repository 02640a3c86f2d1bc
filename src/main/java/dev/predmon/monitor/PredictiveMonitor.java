package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.SafetyRule;
import dev.predmon.compact.IoPair;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;
import dev.predmon.pipeline.PipelineListener;
import dev.predmon.pipeline.TracePipeline;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.Consumer;

/**
 * The predictive monitor: the thesis's Algorithm 8 with MatchTracesRT, made incremental. Records are pushed
 * one at a time through the shared {@link TracePipeline}; each compacted pair advances every model still alive
 * by its two Mealy steps ({@code input/OK}, {@code Delta/output}); a model is dropped at an input it cannot take
 * or when its discrepancies exceed the threshold. A scenario matches while any of its machines matches.
 *
 * <p>The warning: every nominal scenario is eliminated while a faulty one still matches, and a faulty model has
 * matched {@code confirm} more pairs since ({@code confirm = 0} is Algorithm 8; the abstraction sets the default,
 * {@link Abstraction#confirm()}). The nominal models are learned from finitely many runs, so a nominal run that does
 * something no training run did (its battery crosses a band while the robot grasps, say) eliminates them all; a
 * faulty model that happens to allow that step would then warn on no evidence but the novelty. With
 * {@code confirm = 1} the faulty model must also predict what happens next.
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
    private Clock clock = Clock.SECONDS;
    private long pairs;
    private int run;
    private long runLine = 1;
    private final List<RunOutcome> finished = new ArrayList<>();
    private MonitorEvent.Warning firstWarning;
    private MonitorEvent.Violation firstViolation;
    private final int confirm;
    /** Pairs matched since every nominal model was eliminated with a faulty one alive; -1 before. */
    private long sinceNominalGone = -1;
    /** Runs before the last restart: the runs after it are numbered on from there. */
    private int runsBefore;
    /** What the pipeline counted before the last restart (it counts from 0 after each). */
    private long recordsBefore;
    private long interfaceRecordsBefore;
    private final Map<String, Long> unmappedBefore = new TreeMap<>();

    /**
     * @param threshold discrepancies a model may accumulate and still match (0: exact matching)
     * @param events    receives every event, in log order
     */
    public PredictiveMonitor(ModelSet models, Abstraction abstraction, int threshold, Consumer<MonitorEvent> events) {
        this(models, abstraction, threshold, abstraction.confirm(), events);
    }

    /**
     * @param threshold discrepancies a model may accumulate and still match (0: exact matching)
     * @param confirm   pairs a faulty model must match after the last nominal model is eliminated before the warning
     * @param events    receives every event, in log order
     */
    public PredictiveMonitor(ModelSet models, Abstraction abstraction, int threshold, int confirm,
                             Consumer<MonitorEvent> events) {
        if (confirm < 0) {
            throw new IllegalArgumentException("confirm must be at least 0, got " + confirm);
        }
        this.confirm = confirm;
        for (LearnedModel m : models.models()) {
            trackers.add(new ModelTracker(m, threshold));
        }
        this.safety = abstraction.safety();
        this.events = events;
        this.pipeline = new TracePipeline(models.tune(abstraction), this);
    }

    /** Takes the next record of the log. */
    public void accept(LogRecord record) {
        pipeline.accept(record);
    }

    /** The log is complete (batch or {@code --no-follow}): pairs still pending are matched. */
    public void endOfInput() {
        pipeline.endOfInput();
    }

    /**
     * The log was truncated or replaced: every model starts over as for a new log, in a new run. The runs before
     * stay, with their warnings and violations: what {@code watch} reports at its end, and its exit code, cover
     * every run watched since it started, whatever rotation came between them.
     */
    public void restart(String reason) {
        if (pipeline.records() > 0) {
            finished.add(current());
        }
        recordsBefore += pipeline.records();
        interfaceRecordsBefore += pipeline.interfaceRecords();
        pipeline.unmapped().forEach((k, n) -> unmappedBefore.merge(k, n, Long::sum));
        pipeline.reset();
        runsBefore = finished.size();
        startRun(runsBefore, 1);
        events.accept(new MonitorEvent.Restarted(reason));
    }

    /** A new run begins in the log: its outcome is kept and every model starts over. */
    @Override
    public void runStarted(int number, LogRecord first) {
        finished.add(current());
        startRun(runsBefore + number, first.line());
        events.accept(new MonitorEvent.RunStarted(run, first.time(), first.line(), first.clock()));
    }

    private void startRun(int number, long line) {
        run = number;
        runLine = line;
        trackers.forEach(ModelTracker::reset);
        warning = null;
        violation = null;
        noMatch = false;
        battery = null;
        pairs = 0;
        sinceNominalGone = -1;
    }

    private RunOutcome current() {
        return new RunOutcome(run, runLine, warning, violation, noMatch, pairs, battery != null);
    }

    /** The outcome of every run so far, the current one last. */
    public List<RunOutcome> runs() {
        List<RunOutcome> all = new ArrayList<>(finished);
        all.add(current());
        return List.copyOf(all);
    }

    @Override
    public void record(LogRecord record) {
        clock = record.clock();
        if (safety.isEmpty()) {
            return;
        }
        double v = safety.get().valueOf(record);
        if (Double.isNaN(v)) {
            return;
        }
        Double before = battery;
        battery = v;
        if (violation == null && safety.get().violatedBy(v)) {
            violation = new MonitorEvent.Violation(record.time(), record.line(), safety.get().name(), v, before,
                    record.clock(), run);
            firstViolation = firstViolation == null ? violation : firstViolation;
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
                        m.faulty(), t.elimination().describe(), trigger.clock(), run));
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
        if (!nominalAlive && !faultyAlive.isEmpty()) {
            sinceNominalGone++;
        }
        if (warning == null && !nominalAlive && !faultyAlive.isEmpty() && sinceNominalGone >= confirm) {
            warning = new MonitorEvent.Warning(trigger.time(), trigger.line(), List.copyOf(faultyAlive), battery, pairs,
                    trigger.clock(), run);
            firstWarning = firstWarning == null ? warning : firstWarning;
            events.accept(warning);
        }
        if (!noMatch && !nominalAlive && faultyAlive.isEmpty()) {
            noMatch = true;
            events.accept(new MonitorEvent.NoMatch(trigger.time(), trigger.line(), trigger.clock(), run));
        }
    }

    /** Records of the log since the start, across truncations and replacements. */
    public long records() {
        return recordsBefore + pipeline.records();
    }

    /** Records of the skill-component interface since the start, mapped or not. */
    public long interfaceRecords() {
        return interfaceRecordsBefore + pipeline.interfaceRecords();
    }

    /** Interface messages no rule maps since the start, by key, sorted. */
    public Map<String, Long> unmapped() {
        Map<String, Long> all = new TreeMap<>(unmappedBefore);
        pipeline.unmapped().forEach((k, n) -> all.merge(k, n, Long::sum));
        return all;
    }

    /** The first warning of the log (of any run), once raised. */
    public Optional<MonitorEvent.Warning> warning() {
        return Optional.ofNullable(firstWarning);
    }

    /** The first safety violation of the log (of any run), once seen. */
    public Optional<MonitorEvent.Violation> violation() {
        return Optional.ofNullable(firstViolation);
    }

    /** The run being matched: 0, then 1, 2, ... in a log that holds several. */
    public int run() {
        return run;
    }

    /**
     * Whether, in some run since the start, a point came where no model, nominal or faulty, matched it any
     * more.
     */
    public boolean noMatch() {
        return noMatch || finished.stream().anyMatch(RunOutcome::noMatch);
    }

    /** Every model's tracker, in model order. */
    public List<ModelTracker> trackers() {
        return List.copyOf(trackers);
    }

    /** Last value on the safety property's channel (the battery level), or null. */
    public Double battery() {
        return battery;
    }

    /** What the log's times count: seconds, or ticks in a log without time stamps (seconds until a record says). */
    public Clock clock() {
        return clock;
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
