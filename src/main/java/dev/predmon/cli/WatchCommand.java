package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.live.Board;
import dev.predmon.live.LiveServer;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.LogSources;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.monitor.RunsSummary;
import dev.predmon.monitor.WarningRule;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.pipeline.Evidence;
import dev.predmon.property.Bound;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;

/** {@code predmon watch}: the predictive monitor on a live log. */
@Command(name = "watch", mixinStandardHelpOptions = true,
        description = {"Follow a log as 'tail -F' does (growth, truncation, replacement; waits for a file that does "
                + "not exist yet), forecast after every pair the probability that the run violates the property and "
                + "the time left, and warn when it reaches the threshold learned with the models, when the run can "
                + "only be a faulty scenario, or when it is beyond every safe training run (--rule forecast, the "
                + "default for models learned with a forecast). --rule match warns as the thesis does: as soon as "
                + "every nominal model is eliminated while a faulty one still matches. The built-in safety monitor "
                + "reports the property's violation alongside.",
                "Several logs (--log repeated, a directory or a glob) are watched in one process, each with its "
                        + "own monitor; each event then names its log.",
                "Ctrl-C (SIGINT), SIGTERM or SIGHUP stops it: it prints the end summary and exits as below.",
                "Exit 6 when the property was violated with no warning before it, else 1 when a warning was raised, "
                        + "5 when no model matches the run any more, 0 otherwise; 3 when the log held nothing to "
                        + "judge (with --no-follow, at the end of the file; while following one log, at once when it "
                        + "is not a monitor log)."})
final class WatchCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    LogAgainstModels input;

    @Mixin
    ConfirmOption confirm;

    @Mixin
    RuleOption rule;

    @Option(names = "--no-follow", description = "Process to the end of the file and exit.")
    boolean noFollow;

    @Option(names = "--eliminations", description = "Also print each model's elimination (--json always does).")
    boolean eliminations;

    @Option(names = "--poll-ms", paramLabel = "MS", defaultValue = "2",
            description = "How often to look for new lines in a log whose changes the operating system does not "
                    + "announce: on a network file system, in a directory that cannot be watched, or every log with "
                    + "--polling (default: ${DEFAULT-VALUE}).")
    long pollMillis;

    @Option(names = "--polling", description = "Look at every log every --poll-ms instead of waiting for the "
            + "operating system's file-change notification (inotify), as for a file system whose notifications "
            + "cannot be trusted. Costs CPU with many logs.")
    boolean polling;

    @Mixin
    HookOptions hookOptions;

    @Mixin
    FollowOptions follow;

    @Mixin
    LiveViewOptions liveView;

    @Mixin
    ConfigOption config;

    private PrintWriter out;
    private PrintWriter err;

    @Override
    public Integer call() throws Exception {
        out = spec.commandLine().getOut();
        err = spec.commandLine().getErr();
        config.complete();
        if (out instanceof Stdout stdout) {
            // the reader of standard output is gone (a broken pipe) or it cannot be written: stop as on a signal
            Thread watching = Thread.currentThread();
            stdout.onFailure(watching::interrupt);
        }
        ModelSet set = input.models();
        Abstraction abstraction = input.abstraction();
        LogSources sources = new LogSources(input.logs);
        boolean several = sources.several();
        if (!several) {
            if (noFollow) {
                input.checkLog();
            } else {
                input.checkLogIfPresent();
            }
        } else if (noFollow) {
            sources.requireFiles();
        }
        if (noFollow && liveView.http != null) {
            throw new ParameterException(spec.commandLine(), "--http shows logs as they grow: not with --no-follow");
        }
        if (noFollow && follow.heartbeatNanos() > 0) {
            throw new ParameterException(spec.commandLine(), "--heartbeat says that logs are followed: not with "
                    + "--no-follow");
        }
        if (!set.hasFaulty()) {
            err.println("predmon: note: " + Terminal.line(set.dir().toString()) + " has no faulty scenario, so no warning can ever be raised");
        }
        WarningRule warnBy = rule.value(set);
        if (set.forecast() == null) {
            err.println("predmon: note: " + Terminal.line(set.dir().toString()) + " was learned without a forecast; warnings follow the match "
                    + "rule. Run 'predmon learn' again to add it");
        }
        Board board = liveView.board(set, abstraction, several, sources.described());
        if (board != null) {
            board.warnsAt(warnBy, set);
        }
        try (LiveServer server = liveView.start(err, board);
             WatchOutputs outputs = new WatchOutputs(out, err, input.json, eliminations || input.json, several,
                     noFollow, hookOptions.open(err, bound(abstraction)), board, abstraction, p -> !sources.named(p),
                     follow.timestamps, follow.heartbeatNanos(), follow.ticks());
             Fleet fleet = new Fleet(set, abstraction, input.threshold(), confirm.value(abstraction), warnBy,
                     outputs)) {
            if (set.forecast() != null) {
                // How far to trust the models, once, before anything they say (and after what can refuse to start).
                set.forecast().scorecards().forEach(c -> c.lines().forEach(l -> err.println("predmon: " + l)));
            }
            sources.find().forEach(fleet::add);
            String stop = "end-of-file";
            if (noFollow) {
                fleet.drain();
            } else {
                sources.missing().forEach(m -> err.println("predmon: waiting for " + Terminal.line(m) + " to appear"));
                err.flush();
                try (StopSignals signals = StopSignals.interrupting(Thread.currentThread())) {
                    fleet.follow(sources, TimeUnit.MILLISECONDS.toNanos(pollMillis), polling);
                    stop = signals.received() != null ? signals.received() : "interrupted";
                }
                Thread.interrupted(); // stopped: the summaries are written in full
                if (outputs.notALog().isPresent()) {
                    return ExitCodes.BAD_INPUT; // said on stderr when it was found
                }
            }
            List<Integer> codes = new ArrayList<>();
            boolean anyJudged = fleet.logs().stream().anyMatch(l -> whyNoVerdict(outputs.evidence(l)).isEmpty());
            for (WatchedLog l : fleet.logs()) {
                Evidence evidence = outputs.evidence(l);
                Optional<String> refused = refusal(evidence);
                Optional<String> misfit = refused.isPresent() ? Optional.empty() : evidence.misfit();
                boolean beside = outputs.besideTheLogs(l);
                if (beside && anyJudged) {
                    continue; // not a log, beside one that was judged: skipped silently
                }
                if ((noFollow || beside) && refused.isPresent()) { // said once, and no summary of nothing
                    if (!several) {
                        throw new BadInputException(refused.get());
                    }
                    err.println("predmon: " + Terminal.line(refused.get()));
                    codes.add(ExitCodes.BAD_INPUT);
                    continue;
                }
                if (noFollow && misfit.isPresent()) { // which messages, by command, then why there is no verdict
                    Problems.unmapped(err, l.path(), l.monitor().unmapped());
                    if (!several) {
                        throw new BadInputException(misfit.get());
                    }
                    err.println("predmon: " + Terminal.line(misfit.get()));
                    codes.add(ExitCodes.BAD_INPUT);
                    continue;
                }
                if (noFollow) {
                    outputs.flushProblems(l);
                }
                Optional<String> why = refused.or(() -> misfit);
                int code = summary(l, outputs, stop, several, why.isEmpty());
                if (why.isPresent()) {
                    err.println("predmon: " + Terminal.line(Files.exists(l.path()) ? why.get()
                            : l.name() + ": stopped before the file appeared; no verdict"));
                    code = ExitCodes.BAD_INPUT;
                }
                codes.add(code);
            }
            err.flush();
            return codes.size() == 1 ? codes.get(0) : ExitCodes.ofLogs(codes);
        }
    }

    /** The bound below which the abstraction's property is violated, NaN without a property. */
    private static double bound(Abstraction abstraction) {
        return abstraction.safety().map(Bound::floor).orElse(Double.NaN);
    }

    /**
     * Why a log can be given no verdict at all: nothing to judge, or (with {@code --no-follow}, where the whole file
     * is known) a file that is mostly not records.
     */
    private Optional<String> refusal(Evidence evidence) {
        Optional<String> missing = evidence.missing();
        return noFollow ? missing.or(evidence::fragment) : missing;
    }

    /** Why a log gets no verdict: {@link #refusal}, or models that do not fit it; empty when it gets one. */
    private Optional<String> whyNoVerdict(Evidence evidence) {
        return refusal(evidence).or(evidence::misfit);
    }

    /**
     * Prints a log's end summary (unmapped messages to stderr) and returns the exit code of its verdict.
     *
     * @param judged whether the log gets a verdict at all
     */
    private int summary(WatchedLog log, WatchOutputs outputs, String stop, boolean several, boolean judged) {
        PredictiveMonitor m = log.monitor();
        Map<String, Long> unmapped = m.unmapped();
        Problems.unmapped(err, log.path(), unmapped);
        List<RunOutcome> runs = m.runs();
        RunsSummary all = m.summary();
        RunOutcome first = all.firstWarned().orElse(runs.get(0));
        long pairs = all.pairs();
        if (input.json) {
            List<PropertyJson> latest = PropertyJson.latest(m.properties(), m.forecast().orElse(null));
            List<RunEnd> perRun = runs.stream().map(r -> new RunEnd(r.run(), r.firstLine(), r.pairs(),
                    r.warning() != null, r.violation() != null, r.lead().orElse(null), r.noMatch(),
                    ForecastJson.of(r.forecast()), r.run() == runs.get(runs.size() - 1).run() ? latest
                    : PropertyJson.of(r.properties()))).toList();
            End end = new End("end", stop, m.records(), pairs, m.warning().isPresent(),
                    m.violation().isPresent(), first.lead().orElse(null), m.clock().unit(), all.noMatch(), perRun,
                    all.runs(), all.dropped(), unmapped, m.rule().id(),
                    ForecastJson.of(runs.get(runs.size() - 1).forecast()), latest);
            out.println(Json.line(Json.stamped(end, several ? log.name() : null, Instant.now())));
        } else {
            if (all.dropped() > 0) {
                out.println("(the first " + all.dropped() + " of " + all.runs() + " runs are counted, not listed)");
            }
            if (all.runs() > 1) {
                for (RunOutcome r : runs) {
                    out.println("run " + r.run() + " (from line " + r.firstLine()
                            + outputs.restartBefore(log, r.run()).map(how -> ", after the log was " + how).orElse("")
                            + "): " + r.pairs() + " compacted pairs; "
                            + (r.warning() != null ? "warning raised" : "no warning")
                            + (r.noMatch() ? ", no model matches the run" : "")
                            + (r.violation() != null ? ", property violated"
                            : r.safetyObserved() ? ", property held" : ", property not observed")
                            + r.lead().map(l -> ", lead " + EventPrinter.span(l, m.clock())).orElse("")
                            + (r.forecast() == null ? "" : "; last forecast " + ForecastWords.line(r.forecast())));
                    if (judged) {
                        (r.run() == runs.get(runs.size() - 1).run() ? PropertyJson.latestLines(m.properties(),
                                m.forecast().orElse(null)) : PropertyJson.lines(r.properties()))
                                .forEach(l -> out.println(stamp(log, several) + l));
                    }
                }
            }
            String verdict = !judged ? "no verdict"
                    : (m.warning().isPresent() ? "warning raised" : "no warning")
                    + (all.noMatch() ? ", no model matches the run" : "")
                    + (m.violation().isPresent() ? ", property violated"
                    : all.safetyObserved() ? ", property held" : ", property not observed");
            out.println((follow.timestamps ? Json.wallTime(Instant.now()) + " " : "")
                    + "end of " + Terminal.line(log.name()) + (stop.equals("end-of-file") ? "" : " (stopped: "
                    + stop + ")") + ": " + m.records() + " records, " + (all.runs() > 1 ? all.runs() + " runs, " : "")
                    + pairs + " compacted pairs; " + verdict);
            if (all.runs() == 1 && judged) {
                PropertyJson.latestLines(m.properties(), m.forecast().orElse(null))
                        .forEach(l -> out.println(stamp(log, several) + l));
            }
            RunOutcome last = runs.get(runs.size() - 1);
            if (all.runs() == 1 && last.forecast() != null) {
                // in a fleet every line names its log
                out.println((several ? Terminal.line(log.name()) + ": " : "") + "last forecast: "
                        + ForecastWords.line(last.forecast()));
            }
        }
        out.flush();
        return ExitCodes.ofMonitor(m);
    }

    /** What begins a property's verdict line: the wall-clock time with --timestamps, the log's name in a fleet. */
    private String stamp(WatchedLog log, boolean several) {
        return (follow.timestamps ? Json.wallTime(Instant.now()) + " " : "") + (several ? Terminal.line(log.name()) + ":"
                : "");
    }

    /** One run's verdict in the {@code end} event. */
    record RunEnd(int run, long line, long pairs, boolean warning, boolean violation, Double lead, boolean noMatch,
                  ForecastJson forecast, List<PropertyJson> properties) {
    }

    /**
     * The {@code end} event. {@code violation} and {@code lead} are the forecast property's; {@code properties} are
     * every property's verdicts on the last run (each run's are in {@code runs}).
     */
    record End(String event, String stop, long records, long pairs, boolean warning, boolean violation, Double lead,
               String unit, boolean noMatch, List<RunEnd> runs, int runCount, int runsNotListed,
               Map<String, Long> unmapped, String rule, ForecastJson forecast, List<PropertyJson> properties) {
    }
}
