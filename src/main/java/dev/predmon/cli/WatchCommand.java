package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.live.Board;
import dev.predmon.live.LiveServer;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.LogSources;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.monitor.WatchedLog;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;

/** {@code predmon watch}: the predictive monitor on a live log. */
@Command(name = "watch", mixinStandardHelpOptions = true,
        description = {"Follow a log as 'tail -F' does (growth, truncation, replacement; waits for a file that does "
                + "not exist yet) and warn as soon as every nominal model is eliminated while a faulty one still "
                + "matches. The built-in safety monitor reports the property's violation alongside.",
                "Several logs (--log repeated, a directory or a glob) are watched in one process, each with its "
                        + "own monitor; each event then names its log.",
                "Ctrl-C (SIGINT) or SIGTERM stops it: it prints the end summary and exits as below.",
                "Exit 1 when a warning was raised, 5 when no model matches the run any more, 0 otherwise; 3 when "
                        + "the log held nothing to judge (with --no-follow, at the end of the file)."})
final class WatchCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    LogAgainstModels input;

    @Mixin
    ConfirmOption confirm;

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
    LiveViewOptions liveView;

    private PrintWriter out;
    private PrintWriter err;

    @Override
    public Integer call() throws Exception {
        out = spec.commandLine().getOut();
        err = spec.commandLine().getErr();
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
        if (!set.hasFaulty()) {
            err.println("predmon: note: " + set.dir() + " has no faulty scenario, so no warning can ever be raised");
        }
        Board board = liveView.board(set, abstraction);
        try (LiveServer server = liveView.start(err, board);
             WatchOutputs outputs = new WatchOutputs(out, err, input.json, eliminations || input.json, several,
                     noFollow, hookOptions.open(err), board, abstraction.name());
             Fleet fleet = new Fleet(set, abstraction, input.threshold(), confirm.value(abstraction), outputs)) {
            sources.find().forEach(fleet::add);
            String stop = "end-of-file";
            if (noFollow) {
                fleet.drain();
            } else {
                sources.missing().forEach(m -> err.println("predmon: waiting for " + m + " to appear"));
                err.flush();
                try (StopSignals signals = StopSignals.interrupting(Thread.currentThread())) {
                    fleet.follow(sources, TimeUnit.MILLISECONDS.toNanos(pollMillis), polling);
                    stop = signals.received() != null ? signals.received() : "interrupted";
                }
                Thread.interrupted(); // stopped: the summaries are written in full
            }
            List<Integer> codes = new ArrayList<>();
            for (WatchedLog l : fleet.logs()) {
                Optional<String> missing = outputs.evidence(l).missing();
                if (noFollow && missing.isPresent()) {
                    if (!several) {
                        throw new BadInputException(missing.get());
                    }
                    err.println("predmon: " + missing.get());
                    codes.add(ExitCodes.BAD_INPUT);
                    continue;
                }
                if (noFollow) {
                    outputs.flushProblems(l);
                }
                int code = summary(l, outputs, stop, several);
                if (missing.isPresent()) {
                    err.println("predmon: " + (Files.exists(l.path()) ? missing.get()
                            : l.name() + ": stopped before the file appeared; no verdict"));
                    code = ExitCodes.BAD_INPUT;
                }
                codes.add(code);
            }
            err.flush();
            return codes.size() == 1 ? codes.get(0) : fleetCode(codes);
        }
    }

    /**
     * The exit code of several logs: a warning in any log is the fleet's warning, else a log no model matched, else
     * a log judged quietly; only when no log held anything to judge is it bad input.
     */
    private static int fleetCode(List<Integer> codes) {
        for (int c : new int[] {ExitCodes.WARNING, ExitCodes.NO_MATCH, ExitCodes.OK}) {
            if (codes.contains(c)) {
                return c;
            }
        }
        return ExitCodes.BAD_INPUT;
    }

    /** Prints a log's end summary (unmapped messages to stderr) and returns the exit code of its verdict. */
    private int summary(WatchedLog log, WatchOutputs outputs, String stop, boolean several) {
        PredictiveMonitor m = log.monitor();
        Map<String, Long> unmapped = m.pipeline().unmapped();
        Problems.unmapped(err, log.path(), unmapped);
        boolean judged = outputs.evidence(log).missing().isEmpty();
        List<RunOutcome> runs = m.runs();
        RunOutcome first = runs.stream().filter(r -> r.warning() != null).findFirst().orElse(runs.get(0));
        long pairs = runs.stream().mapToLong(RunOutcome::pairs).sum();
        if (input.json) {
            List<RunEnd> perRun = runs.stream().map(r -> new RunEnd(r.run(), r.firstLine(), r.pairs(),
                    r.warning() != null, r.violation() != null, r.lead().orElse(null), r.noMatch())).toList();
            End end = new End("end", stop, m.pipeline().records(), pairs, m.warning().isPresent(),
                    m.violation().isPresent(), first.lead().orElse(null), m.clock().unit(), m.noMatch(), perRun,
                    unmapped);
            out.println(Json.line(several ? Json.tagged(end, log.name()) : end));
        } else {
            if (runs.size() > 1) {
                for (RunOutcome r : runs) {
                    out.println("run " + r.run() + " (from line " + r.firstLine() + "): " + r.pairs() + " compacted pairs; "
                            + (r.warning() != null ? "warning raised" : "no warning")
                            + (r.noMatch() ? ", no model matches the run" : "")
                            + (r.violation() != null ? ", property violated"
                            : r.safetyObserved() ? ", property held" : ", property not observed")
                            + r.lead().map(l -> ", lead " + EventPrinter.span(l, m.clock())).orElse(""));
                }
            }
            String verdict = !judged ? "no verdict"
                    : (m.warning().isPresent() ? "warning raised" : "no warning")
                    + (m.noMatch() ? ", no model matches the run" : "")
                    + (m.violation().isPresent() ? ", property violated"
                    : runs.stream().anyMatch(RunOutcome::safetyObserved) ? ", property held" : ", property not observed");
            out.println("end of " + log.name() + (stop.equals("end-of-file") ? "" : " (stopped: " + stop + ")") + ": "
                    + m.pipeline().records() + " records, " + (runs.size() > 1 ? runs.size() + " runs, " : "")
                    + pairs + " compacted pairs; " + verdict);
        }
        out.flush();
        return runs.size() == 1 ? ExitCodes.of(m.noMatch(), m.warning().isPresent())
                : ExitCodes.ofRuns(runs.stream().mapToInt(r -> ExitCodes.of(r.noMatch(), r.warning() != null)));
    }

    /** One run's verdict in the {@code end} event. */
    record RunEnd(int run, long line, long pairs, boolean warning, boolean violation, Double lead, boolean noMatch) {
    }

    /** The {@code end} event. */
    record End(String event, String stop, long records, long pairs, boolean warning, boolean violation, Double lead,
               String unit, boolean noMatch, List<RunEnd> runs, Map<String, Long> unmapped) {
    }
}
