package dev.predmon.cli;

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
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;

/** {@code predmon watch}: the predictive monitor on a live log. */
@Command(name = "watch", mixinStandardHelpOptions = true,
        description = {"Follow a log as 'tail -F' does (growth, truncation, replacement; waits for a file that does "
                + "not exist yet) and warn as soon as every nominal model is eliminated while a faulty one still "
                + "matches. The built-in safety monitor reports the property's violation alongside.",
                "Several logs (--log repeated, a directory or a glob) are watched in one process, each with its "
                + "own monitor; each event then names its log.",
                "Exit 1 when a warning was raised (in any log), 0 otherwise (with --no-follow, at the end of the file)."})
final class WatchCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--log", required = true, paramLabel = "FILE|DIR|GLOB",
            description = "The log to watch. Repeat it, or name a directory (its *.log and *.txt files, also those "
                    + "that appear later) or a quoted glob ('logs/robot-*.log'), to watch several logs at once.")
    List<Path> logs;

    @Mixin
    ThresholdOption threshold;

    @Mixin
    ConfirmOption confirm;

    @Option(names = "--json", description = "One JSON object per event on stdout.")
    boolean json;

    @Option(names = "--no-follow", description = "Process to the end of the file and exit.")
    boolean noFollow;

    @Option(names = "--eliminations", description = "Also print each model's elimination (--json always does).")
    boolean eliminations;

    @Option(names = "--poll-ms", paramLabel = "MS", defaultValue = "2", description = "How often to look for new lines (default: ${DEFAULT-VALUE}).")
    long pollMillis;

    @Mixin
    HookOptions hookOptions;

    @Mixin
    LiveViewOptions liveView;

    @Mixin
    ModelOptions models;

    @Mixin
    AbstractionOption abstractionOption;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Abstraction abstraction = abstractionOption.load();
        ModelSet set = models.load(abstraction);
        LogSources sources = new LogSources(logs);
        if (noFollow) {
            sources.requireFiles();
        }
        if (!set.hasFaulty()) {
            err.println("predmon: note: " + set.dir() + " has no faulty scenario, so no warning can ever be raised");
        }
        if (noFollow && liveView.http != null) {
            throw new ParameterException(spec.commandLine(), "--http shows logs as they grow: not with --no-follow");
        }
        boolean several = sources.several();
        Board board = liveView.board(set, abstraction);
        try (LiveServer server = liveView.start(err, board);
             WatchOutputs outputs = new WatchOutputs(out, err, json, eliminations || json, several,
                     hookOptions.open(err), board);
             Fleet fleet = new Fleet(set, abstraction, threshold.value, confirm.value(abstraction), outputs)) {
            sources.find().forEach(fleet::add);
            if (noFollow) {
                fleet.drain();
                for (WatchedLog l : fleet.logs()) {
                    summary(out, err, l.path(), l.monitor(), several);
                }
            } else {
                sources.missing().forEach(m -> err.println("predmon: waiting for " + m + " to appear"));
                err.flush();
                // Until the thread is interrupted, which is how watching is meant to end (Ctrl-C ends the JVM).
                fleet.follow(sources, pollMillis);
            }
            return fleet.warned() ? ExitCodes.WARNING : ExitCodes.OK;
        }
    }

    private void summary(PrintWriter out, PrintWriter err, Path log, PredictiveMonitor m, boolean several) {
        Map<String, Long> unmapped = m.pipeline().unmapped();
        Problems.interfaceMessages(err, log, m.pipeline().records(), m.pipeline().interfaceRecords(), unmapped);
        List<RunOutcome> runs = m.runs();
        RunOutcome first = runs.stream().filter(r -> r.warning() != null).findFirst().orElse(runs.get(0));
        if (json) {
            Map<String, Object> o = new LinkedHashMap<>();
            o.put("event", "end");
            if (several) {
                o.put("log", log.toString());
            }
            o.put("records", m.pipeline().records());
            o.put("pairs", runs.stream().mapToLong(RunOutcome::pairs).sum());
            o.put("warning", m.warning().isPresent());
            o.put("violation", m.violation().isPresent());
            o.put("lead", first.lead().orElse(null));
            o.put("unit", m.clock().unit());
            List<Map<String, Object>> perRun = new ArrayList<>();
            for (RunOutcome r : runs) {
                Map<String, Object> x = new LinkedHashMap<>();
                x.put("run", r.run());
                x.put("line", r.firstLine());
                x.put("pairs", r.pairs());
                x.put("warning", r.warning() != null);
                x.put("violation", r.violation() != null);
                x.put("lead", r.lead().orElse(null));
                x.put("noMatch", r.noMatch());
                perRun.add(x);
            }
            o.put("runs", perRun);
            o.put("unmapped", unmapped);
            out.println(EventPrinter.write(o));
        } else {
            if (runs.size() > 1) {
                for (RunOutcome r : runs) {
                    out.println("run " + r.run() + " (from line " + r.firstLine() + "): " + r.pairs() + " compacted pairs; "
                            + (r.warning() != null ? "warning raised" : "no warning")
                            + (r.violation() != null ? ", property violated" : ", property held")
                            + r.lead().map(l -> ", lead " + EventPrinter.span(l, m.clock())).orElse(""));
                }
            }
            out.println("end of " + log + ": " + m.pipeline().records() + " records, " + runs.size() + " run(s), "
                    + runs.stream().mapToLong(RunOutcome::pairs).sum() + " compacted pairs; "
                    + (m.warning().isPresent() ? "warning raised" : "no warning")
                    + (m.violation().isPresent() ? ", property violated" : ", property held"));
        }
        out.flush();
    }
}
