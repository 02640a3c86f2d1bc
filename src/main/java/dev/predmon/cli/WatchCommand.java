package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.LogWatcher;
import dev.predmon.monitor.PredictiveMonitor;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;

/** {@code predmon watch}: the predictive monitor on a live log. */
@Command(name = "watch", mixinStandardHelpOptions = true,
        description = {"Follow a log as 'tail -F' does (growth, truncation, replacement; waits for a file that does "
                + "not exist yet) and warn as soon as every nominal model is eliminated while a faulty one still "
                + "matches. The built-in safety monitor reports the property's violation alongside.",
                "Exit 1 when a warning was raised, 0 otherwise (with --no-follow, at the end of the file)."})
final class WatchCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--log", required = true, paramLabel = "FILE", description = "The log to watch.")
    Path log;

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
    ModelOptions models;

    @Mixin
    AbstractionOption abstractionOption;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Abstraction abstraction = abstractionOption.load();
        ModelSet set = models.load(abstraction);
        if (Files.isDirectory(log)) {
            throw new BadInputException(log + ": is a directory; expected a log file");
        }
        if (noFollow && !Files.exists(log)) {
            throw new BadInputException(log + ": no such file");
        }
        if (!set.hasFaulty()) {
            err.println("predmon: note: " + set.dir() + " has no faulty scenario, so no warning can ever be raised");
        }
        EventPrinter printer = new EventPrinter(out, json, eliminations || json);
        PredictiveMonitor monitor = new PredictiveMonitor(set, abstraction, threshold.value, confirm.value(abstraction), printer);
        try (LogWatcher watcher = new LogWatcher(log, monitor, p -> {
            err.println(p.format(log.toString()));
            err.flush();
        })) {
            if (noFollow) {
                watcher.drain();
                summary(out, err, monitor);
            } else {
                if (!Files.exists(log)) {
                    err.println("predmon: waiting for " + log + " to appear");
                    err.flush();
                }
                follow(watcher);
            }
        }
        return monitor.warning().isPresent() ? ExitCodes.WARNING : ExitCodes.OK;
    }

    /**
     * Follows until the thread is interrupted, which is how watching is meant to end (Ctrl-C in a shell ends the
     * JVM instead): an interrupt while sleeping or reading is a stop, not an error.
     */
    private void follow(LogWatcher watcher) throws java.io.IOException {
        try {
            while (!Thread.currentThread().isInterrupted()) {
                if (!watcher.poll()) {
                    Thread.sleep(pollMillis);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (java.nio.channels.ClosedByInterruptException e) {
            // interrupted while reading (FileChannel reads are interruptible); the interrupt status stays set
        }
    }

    private void summary(PrintWriter out, PrintWriter err, PredictiveMonitor m) {
        Map<String, Long> unmapped = m.pipeline().unmapped();
        Problems.interfaceMessages(err, log, m.pipeline().records(), m.pipeline().interfaceRecords(), unmapped);
        if (json) {
            Map<String, Object> o = new LinkedHashMap<>();
            o.put("event", "end");
            o.put("records", m.pipeline().records());
            o.put("pairs", m.pairs());
            o.put("warning", m.warning().isPresent());
            o.put("violation", m.violation().isPresent());
            o.put("lead", m.warning().isPresent() && m.violation().isPresent()
                    ? m.violation().get().time() - m.warning().get().time() : null);
            o.put("unit", m.clock().unit());
            o.put("unmapped", unmapped);
            out.println(EventPrinter.write(o));
        } else {
            out.println("end of " + log + ": " + m.pipeline().records() + " records, " + m.pairs() + " compacted pairs; "
                    + (m.warning().isPresent() ? "warning raised" : "no warning")
                    + (m.violation().isPresent() ? ", property violated" : ", property held"));
        }
        out.flush();
    }
}
