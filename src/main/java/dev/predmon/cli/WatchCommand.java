package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.LogWatcher;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.parse.ParseProblem;
import dev.predmon.pipeline.Evidence;
import dev.predmon.pipeline.Traces;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.channels.ClosedByInterruptException;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;

/** {@code predmon watch}: the predictive monitor on a live log. */
@Command(name = "watch", mixinStandardHelpOptions = true,
        description = {"Follow a log as 'tail -F' does (growth, truncation, replacement; waits for a file that does "
                + "not exist yet) and warn as soon as every nominal model is eliminated while a faulty one still "
                + "matches. The built-in safety monitor reports the property's violation alongside.",
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

    @Option(names = "--poll-ms", paramLabel = "MS", defaultValue = "2", description = "How often to look for new lines (default: ${DEFAULT-VALUE}).")
    long pollMillis;

    private PrintWriter out;
    private PrintWriter err;
    /** With --no-follow, problems wait for the end: a log with nothing to judge gets one line, not a list. */
    private final List<ParseProblem> heldProblems = new ArrayList<>();
    private long moreProblems;
    private ParseProblem firstProblem;

    @Override
    public Integer call() throws Exception {
        out = spec.commandLine().getOut();
        err = spec.commandLine().getErr();
        ModelSet set = input.models();
        Abstraction abstraction = input.abstraction();
        if (noFollow) {
            input.checkLog();
        } else {
            input.checkLogIfPresent();
        }
        if (!set.hasFaulty()) {
            err.println("predmon: note: " + set.dir() + " has no faulty scenario, so no warning can ever be raised");
        }
        EventPrinter printer = new EventPrinter(out, input.json, eliminations || input.json);
        PredictiveMonitor monitor = new PredictiveMonitor(set, abstraction, input.threshold(),
                confirm.value(abstraction), e -> {
            if (e instanceof MonitorEvent.Unmapped u) {
                if (!noFollow) { // first sighting of each kind while following; with --no-follow the totals say it
                    err.println(input.log + ":" + u.line() + ": warning: interface message no abstraction rule maps: "
                            + u.message() + " (first of its kind; the totals come at the stop)");
                    err.flush();
                }
            } else {
                printer.accept(e);
            }
        });
        try (LogWatcher watcher = new LogWatcher(input.log, monitor, this::problem)) {
            if (noFollow) {
                watcher.drain();
                Optional<String> missing = evidence(watcher, abstraction).missing();
                if (missing.isPresent()) {
                    throw new BadInputException(missing.get());
                }
                heldProblems.forEach(p -> err.println(p.format(input.log.toString())));
                if (moreProblems > 0) {
                    err.println(input.log + ": " + moreProblems + " more problem(s) not shown");
                }
                return summary(watcher, abstraction, "end-of-file");
            }
            if (!Files.exists(input.log)) {
                err.println("predmon: waiting for " + input.log + " to appear");
                err.flush();
            }
            String stop;
            try (StopSignals signals = StopSignals.interrupting(Thread.currentThread())) {
                follow(watcher, abstraction);
                stop = signals.received() != null ? signals.received() : "interrupted";
            }
            Thread.interrupted(); // stopped: the summary is written in full
            int code = summary(watcher, abstraction, stop);
            Optional<String> missing = evidence(watcher, abstraction).missing();
            if (missing.isPresent()) {
                err.println("predmon: " + (Files.exists(input.log) ? missing.get()
                        : input.log + ": stopped before the file appeared; no verdict"));
                err.flush();
                return ExitCodes.BAD_INPUT;
            }
            return code;
        }
    }

    private void problem(ParseProblem p) {
        if (firstProblem == null) {
            firstProblem = p;
        }
        if (!noFollow) {
            err.println(p.format(input.log.toString()));
            err.flush();
        } else if (heldProblems.size() < Traces.MAX_PROBLEMS) {
            heldProblems.add(p);
        } else {
            moreProblems++;
        }
    }

    private Evidence evidence(LogWatcher watcher, Abstraction abstraction) {
        PredictiveMonitor m = watcher.monitor();
        return new Evidence(input.log, watcher::lines, m.pipeline().records(), m.pipeline().interfaceRecords(),
                m.pairs(), m.pipeline().unmapped(), abstraction.name(), firstProblem);
    }

    /**
     * Follows until the thread is interrupted, which is how watching ends: by SIGINT or SIGTERM
     * ({@link StopSignals}) or by an interrupt when run in-process. An interrupt while sleeping or reading is a
     * stop, not an error. After the first lines, says once if nothing recognisable has arrived.
     */
    private void follow(LogWatcher watcher, Abstraction abstraction) throws IOException {
        boolean settled = false; // something recognisable arrived, or the notice was given
        try {
            while (!Thread.currentThread().isInterrupted()) {
                boolean read = watcher.poll();
                if (read && !settled) {
                    Evidence evidence = evidence(watcher, abstraction);
                    Optional<String> notice = evidence.earlyNotice();
                    notice.ifPresent(n -> {
                        err.println("predmon: " + n);
                        err.flush();
                    });
                    settled = notice.isPresent() || evidence.recognised();
                }
                if (!read) {
                    Thread.sleep(pollMillis);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ClosedByInterruptException e) {
            // interrupted while reading (FileChannel reads are interruptible); the interrupt status stays set
        }
    }

    /** Prints the end summary (unmapped messages to stderr) and returns the exit code of the run's verdict. */
    private int summary(LogWatcher watcher, Abstraction abstraction, String stop) {
        PredictiveMonitor m = watcher.monitor();
        Map<String, Long> unmapped = m.pipeline().unmapped();
        Problems.unmapped(err, input.log, unmapped);
        boolean judged = evidence(watcher, abstraction).missing().isEmpty();
        List<RunOutcome> runs = m.runs();
        RunOutcome first = runs.stream().filter(r -> r.warning() != null).findFirst().orElse(runs.get(0));
        long pairs = runs.stream().mapToLong(RunOutcome::pairs).sum();
        if (input.json) {
            List<RunEnd> perRun = runs.stream().map(r -> new RunEnd(r.run(), r.firstLine(), r.pairs(),
                    r.warning() != null, r.violation() != null, r.lead().orElse(null), r.noMatch())).toList();
            out.println(Json.line(new End("end", stop, m.pipeline().records(), pairs, m.warning().isPresent(),
                    m.violation().isPresent(), first.lead().orElse(null), m.clock().unit(), m.noMatch(), perRun,
                    unmapped)));
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
            out.println("end of " + input.log + (stop.equals("end-of-file") ? "" : " (stopped: " + stop + ")") + ": "
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
