package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.compact.IoPair;
import dev.predmon.forecast.Forecast;
import dev.predmon.matching.MatchRule;
import dev.predmon.matching.Matching;
import dev.predmon.matching.ModelTracker;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;
import dev.predmon.pipeline.PipelineListener;
import dev.predmon.pipeline.TracePipeline;
import dev.predmon.property.Bound;
import dev.predmon.property.PropertyChecker.PropertyVerdict;
import dev.predmon.property.PropertyView;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.ObjIntConsumer;

/**
 * The predictive monitor: the thesis's Algorithm 8 with MatchTracesRT, made incremental. Records are pushed
 * one at a time through the shared {@link TracePipeline}; each compacted pair advances every model still alive
 * by its two Mealy steps ({@code input/OK}, {@code Delta/output}) ({@link Matching}); a model is dropped at an input
 * it cannot take or when its discrepancies exceed the tolerance. A scenario matches while any of its machines
 * matches. The match rule ({@link MatchRule}): every nominal scenario eliminated while a faulty one still matches, for
 * {@code confirm} more pairs ({@link Abstraction#confirm()}). Per record the work and the state are constant.
 *
 * <p>Every property of the abstraction is followed the same way ({@link PropertyFollows}): the checker judges it, its
 * follower forecasts it where the models learned a forecast of it (a probability of violation and a time to it, also
 * through behaviour no model has seen), warns by the rule in force ({@link WarningRule#FORECAST} by default, the
 * thesis's {@link WarningRule#MATCH}) and says when a warning or a violation is over. One property, the abstraction's
 * first floor ({@link Abstraction#safety()}), is the run's headline: the outcome's older fields ({@link RunOutcome}'s
 * warning and violation, the wire's {@code battery}) speak of it.
 */
public final class PredictiveMonitor implements PipelineListener {

    private final Matching matching;
    private final PropertyFollows properties;
    private final Consumer<MonitorEvent> events;
    private final TracePipeline pipeline;
    /** What the current run has shown so far; starts over with every run. */
    private final RunState now = new RunState();
    private Clock clock = Clock.SECONDS;
    private final RunHistory finished = new RunHistory();
    /** Runs before the last restart: the runs after it are numbered on from there. */
    private int runsBefore;
    private final LogTotals before = new LogTotals();
    private final WarningRule rule;
    private final FollowContext context;
    private ObjIntConsumer<Forecast> everyForecast = (f, r) -> { };
    private BoundSteps everyBound = (p, f, r) -> { };
    private TickSeconds ticks = TickSeconds.NONE;
    /** Sees what the pipeline gives the monitor, each just before the monitor takes it (the replay's stream). */
    private PipelineListener tee = (pair, trigger) -> { };

    /** As below, confirming as the abstraction says ({@link Abstraction#confirm()}). */
    public PredictiveMonitor(ModelSet models, Abstraction abstraction, int tolerance, Consumer<MonitorEvent> events) {
        this(models, abstraction, tolerance, abstraction.confirm(), events);
    }

    /** As below, warning by {@link #defaultRule}. */
    public PredictiveMonitor(ModelSet models, Abstraction abstraction, int tolerance, int confirm,
                             Consumer<MonitorEvent> events) {
        this(models, abstraction, tolerance, confirm, defaultRule(models), events);
    }

    /**
     * @param tolerance discrepancies a model may accumulate and still match (0: exact matching)
     * @param confirm   pairs a faulty model must match after the last nominal model is eliminated before the match
     *                  rule's warning
     * @param rule      when to warn; {@link WarningRule#FORECAST} needs models learned with a forecast
     * @param events    receives every event, in log order
     */
    public PredictiveMonitor(ModelSet models, Abstraction abstraction, int tolerance, int confirm, WarningRule rule,
                             Consumer<MonitorEvent> events) {
        if (rule == WarningRule.FORECAST && models.forecast() == null) {
            throw new IllegalArgumentException("the forecast rule needs models learned with a forecast");
        }
        this.rule = rule;
        this.matching = new Matching(models.models(), tolerance, confirm);
        String headline = abstraction.safety().map(Bound::id).orElse(null);
        this.events = e -> events.accept(ticks.event(now.told(e, headline))); // in seconds once a tick is given
        this.context = new FollowContext(now, rule, this.events, matching, headline);
        context.bounds = (p, f, run) -> {
            if (p.equals(context.headline)) {
                everyForecast.accept(f, run);
            } else {
                everyBound.forecast(p, f, run);
            }
        };
        this.properties = new PropertyFollows(models, abstraction, context);
        this.pipeline = new TracePipeline(models.tune(abstraction), this);
    }

    /** Reports every time in seconds, a tick lasting {@code t} (a log without time stamps counts ticks). */
    public void countTicksAs(TickSeconds t) {
        ticks = t;
        properties.countTicksAs(t);
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
        properties.runEnded(now.last, "the run ended: " + MonitorEvent.Restarted.words(reason)
                + "; what follows is a new run");
        if (pipeline.records() > 0) {
            finished.add(current());
        }
        before.add(pipeline);
        pipeline.reset();
        runsBefore = finished.count();
        startRun(runsBefore, 1);
        events.accept(new MonitorEvent.Restarted(reason));
    }

    /** A new run begins in the log: its outcome is kept and every model starts over. */
    @Override
    public void runStarted(int number, LogRecord first) {
        tee.runStarted(number, first);
        properties.ending(first); // a deadline the silence before it passed is violated, not dropped
        properties.runEnded(first, "the run ended; a new run began at line " + first.line());
        finished.add(current());
        startRun(runsBefore + number, first.line());
        events.accept(new MonitorEvent.RunStarted(now.run, first.time(), first.line(), first.clock()));
    }

    /** The rule used when none is asked for: the forecast's when held-out runs chose its threshold, else the thesis's. */
    public static WarningRule defaultRule(ModelSet models) {
        return models.forecast() != null && models.forecast().validated() ? WarningRule.FORECAST : WarningRule.MATCH;
    }

    private void startRun(int number, long line) {
        now.start(number, line);
        matching.reset();
        properties.reset();
    }

    private RunOutcome current() {
        return new RunOutcome(now.run, now.firstLine, (MonitorEvent.Warning) ticks.event(now.warning),
                (MonitorEvent.Violation) ticks.event(now.violation), now.noMatch, now.pairs,
                properties.headline() != null && properties.headline().observed(), forecast().orElse(null),
                properties.verdicts(), (MonitorEvent.Warning) ticks.event(now.anyWarning),
                RunOutcome.inSeconds(now.warnings, ticks::event), now.warningRead, now.violationRead);
    }

    /** Every run's outcome, the current one last: the latest {@value RunHistory#KEPT} ({@link #summary}: all). */
    public List<RunOutcome> runs() {
        return finished.withCurrent(current());
    }

    /** Every property of the current run with its verdict so far, in the abstraction's order. */
    public List<PropertyVerdict> verdicts() {
        return properties.verdicts();
    }

    /**
     * Every property of the current run now, in the abstraction's order: its verdict, whether a warning of it is up,
     * what forecasts it and its latest forecast (the forecast's property's is {@link #forecast()}).
     */
    public List<PropertyStatus> properties() {
        return properties.statuses();
    }

    /** What all runs since the start add up to. */
    public RunsSummary summary() {
        return finished.summary(current());
    }

    /** A record: every property's violation, recovery, forecast and warning at it ({@link PropertyFollow}). */
    @Override
    public void record(LogRecord record) {
        tee.record(record);
        now.read++;
        clock = ticks.clock(record.clock());
        now.last = record;
        properties.record(record);
    }

    @Override
    public void unmapped(UnmappedMessage message, LogRecord record) {
        tee.unmapped(message, record);
        events.accept(new MonitorEvent.Unmapped(record.time(), record.line(), message));
    }

    @Override
    public void gap(LogRecord record) {
        tee.gap(record);
        properties.gap(record.line());
    }

    @Override
    public void pair(IoPair pair, LogRecord trigger) {
        tee.pair(pair, trigger);
        now.pairs++;
        Matching.Step step = matching.pair(pair);
        if (step.ruleWarns() && now.matchRuleAt < 0) {
            now.matchRuleAt = now.pairs - 1;
        }
        for (ModelTracker t : step.eliminated()) {
            LearnedModel m = t.model();
            events.accept(new MonitorEvent.Eliminated(trigger.time(), trigger.line(), m.id(), m.scenario(),
                    m.faulty(), t.elimination().describe(), trigger.clock(), now.run));
        }
        properties.pair(pair, step, trigger);
        if (!now.noMatch && step.noMatch()) {
            now.noMatch = true;
            events.accept(new MonitorEvent.NoMatch(trigger.time(), trigger.line(), trigger.clock(), now.run));
        }
    }

    /** Records of the log since the start, across truncations and replacements. */
    public long records() {
        return before.records(pipeline);
    }

    /** Records of the skill-component interface since the start, mapped or not. */
    public long interfaceRecords() {
        return before.interfaceRecords(pipeline);
    }

    /** Interface messages no rule maps since the start, by key, sorted. */
    public Map<UnmappedMessage, Long> unmapped() {
        return before.unmapped(pipeline);
    }

    /** Also tells {@code each} every forecast with its run, one per pair, before that pair's events (for scoring). */
    public void onEveryForecast(ObjIntConsumer<Forecast> each) {
        this.everyForecast = each;
    }

    /** Also tells {@code each} every forecast of each bound property but the headline one. */
    public void onEveryBoundForecast(BoundSteps each) {
        this.everyBound = each;
    }

    /**
     * Also tells {@code each} every raw deadline forecast and how each obligation so forecast ended ({@link
     * DeadlineSteps}); nothing without deadline forecasts (models without obligations).
     */
    public void onEveryDeadlineForecast(DeadlineSteps each) {
        context.deadlines = each;
    }

    /**
     * Also tells {@code also} each record, gap, pair and run start the pipeline gives the monitor, just before it takes
     * it: one stream for the replay ({@code dev.predmon.replay}), in the monitor's own order.
     */
    public void tee(PipelineListener also) {
        this.tee = also;
    }

    /** The id of the property the monitor's own forecast and the match rule's warnings are about, if any. */
    public Optional<String> forecastProperty() {
        return Optional.ofNullable(context.headline);
    }

    /** The rule this monitor warns by. */
    public WarningRule rule() {
        return rule;
    }

    /** The latest forecast of the current run, if the models carry one and a pair has come. */
    public Optional<Forecast> forecast() {
        return Optional.ofNullable(properties.headline() == null ? null : properties.headline().last());
    }

    /** The first warning of the log (of any run), once raised. */
    public Optional<MonitorEvent.Warning> warning() {
        return Optional.ofNullable((MonitorEvent.Warning) ticks.event(now.firstWarning));
    }

    /** The forecast property's first violation in the log (of any run), once seen. */
    public Optional<MonitorEvent.Violation> violation() {
        return Optional.ofNullable((MonitorEvent.Violation) ticks.event(now.firstViolation));
    }

    /** The run being matched: 0, then 1, 2, ... in a log that holds several. */
    public int run() {
        return now.run;
    }

    /** Whether, in some run since the start, a point came where no model, nominal or faulty, matched it any more. */
    public boolean noMatch() {
        return now.noMatch || finished.noMatch();
    }

    /** Every model's tracker, in model order. */
    public List<ModelTracker> trackers() {
        return matching.trackers();
    }

    /** What the log's times count: seconds, or ticks in a log without time stamps (seconds until a record says). */
    public Clock clock() {
        return clock;
    }

    /**
     * The pair (0-based) of the current run after which the thesis's match rule first held, {@code confirm} pairs
     * included, whether or not the rule in force warned there; -1 while it has not.
     */
    public long matchRuleAt() {
        return now.matchRuleAt;
    }

    /** Compacted pairs matched so far. */
    public long pairs() {
        return now.pairs;
    }

    /**
     * Every property of the current run as the checker judged the last record (read-only): the one reader of a
     * property's value, for whoever shows, labels or scores it.
     */
    public PropertyView judged() {
        return properties.checker();
    }

    /** The pipeline's counters (records, interface records, unmapped messages). */
    public TracePipeline pipeline() {
        return pipeline;
    }
}
