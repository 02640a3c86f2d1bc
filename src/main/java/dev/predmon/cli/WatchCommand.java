package dev.predmon.cli;

import dev.predmon.Terminal;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.live.Board;
import dev.predmon.live.LiveServer;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.LogSources;
import dev.predmon.monitor.WarningRule;
import dev.predmon.property.Bound;
import dev.predmon.rosbridge.RosbridgeClient;
import dev.predmon.watch.Stamp;
import dev.predmon.watch.WatchSession;
import dev.predmon.watch.WatchSettings;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
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
                "Exit 6 when a property (any of them) was violated with no warning of any property before it, else "
                        + "1 when a warning was raised (a deadline's too), "
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

    private long pollMillis = 2;

    @Option(names = "--poll-ms", paramLabel = "MS", defaultValue = "2",
            description = "How often to look for new lines in a log whose changes the operating system does not "
                    + "announce: on a network file system, in a directory that cannot be watched, or every log with "
                    + "--polling; from 1 to 60000 (default: ${DEFAULT-VALUE}).")
    void pollMillis(long millis) {
        if (millis < 1 || millis > 60_000) {
            // 0 or less would look without a pause, a core spent on nothing
            throw new ParameterException(spec.commandLine(), "--poll-ms must be from 1 to 60000 milliseconds, got "
                    + millis);
        }
        pollMillis = millis;
    }

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

    @Mixin
    RosbridgeOptions rosbridge;


    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        config.complete();
        if (out instanceof Stdout stdout) {
            // the reader of standard output is gone (a broken pipe) or it cannot be written: stop as on a signal
            Thread watching = Thread.currentThread();
            stdout.onFailure(watching::interrupt);
        }
        ModelSet set = input.models();
        Abstraction abstraction = input.abstraction();
        rosbridge.check(spec, input.logs != null, noFollow, abstraction);
        // usage errors before anything is read
        if (noFollow && liveView.http != null) {
            throw new ParameterException(spec.commandLine(), "--http shows logs as they grow: not with --no-follow");
        }
        if (noFollow && follow.heartbeatNanos() > 0) {
            throw new ParameterException(spec.commandLine(), "--heartbeat says that logs are followed: not with "
                    + "--no-follow");
        }
        LogSources sources = rosbridge.given() ? LogSources.none() : new LogSources(input.logs());
        boolean several = sources.several();
        if (rosbridge.given()) {
            polling = true; // the robot's messages come on a socket: no file change to be told of
        } else if (!several) {
            if (noFollow) {
                input.checkLogHoldsRecords(abstraction);
            } else {
                input.checkLogIfPresent();
            }
        } else if (noFollow) {
            sources.requireFiles();
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
        WatchSettings settings = new WatchSettings(input.json, eliminations || input.json, several, noFollow,
                follow.timestamps ? Stamp.WALL_CLOCK : Stamp.NONE, follow.heartbeatNanos(), follow.ticks());
        try (RosbridgeClient robot = rosbridge.given() ? rosbridge.start(spec, abstraction, err) : null;
             LiveServer server = liveView.start(err, board);
             WatchSession session = new WatchSession(out, err, settings, hookOptions.open(err, bound(abstraction), abstraction.properties()),
                     board, abstraction, p -> !sources.named(p));
             Fleet fleet = new Fleet(set, abstraction, input.tolerance(), confirm.value(abstraction), warnBy,
                     rosbridge.listener(session, robot))) {
            if (set.forecast() != null) {
                // How far to trust the models, once, before anything they say (and after what can refuse to start).
                set.forecast().allScorecards().forEach(c -> c.lines().forEach(l -> err.println("predmon: " + l)));
            }
            sources.find().forEach(fleet::add);
            if (robot != null) {
                rosbridge.add(fleet, abstraction, robot);
            }
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
            }
            return session.finish(fleet, stop);
        }
    }

    /** The bound below which the abstraction's property is violated, NaN without a property. */
    private static double bound(Abstraction abstraction) {
        return abstraction.safety().map(Bound::floor).orElse(Double.NaN);
    }
}
