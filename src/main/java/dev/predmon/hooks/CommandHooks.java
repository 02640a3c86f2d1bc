package dev.predmon.hooks;

import dev.predmon.event.LogEvent;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.property.Property;

import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Delivers warnings and violations to the robot: {@code --on-warning CMD} and {@code --on-violation CMD} run a shell
 * command for each such event, and {@code --on-recovered CMD} for each recovery, so that an alarm raised on the robot
 * ends when its cause ends, with the event's JSON (one line) on its standard input and its main fields in
 * environment variables ({@link HookEnvironment}). This is the thesis's future work made possible: the deliberation
 * layer hears of the predicted failure while a recovery action can still help.
 *
 * <p>The monitor is never held up: {@link #event} only queues the command. At most {@value #THREADS} commands run at
 * once; each log's commands wait in a queue of their own, at most {@value #PER_LOG} of them, and the logs take turns
 * ({@link HookQueue}), so one robot's storm never keeps another robot's warning from its command. A recovery runs
 * its command only once the alarm has stayed over for the hold time ({@link AlarmHold}), so a reading flapping at the
 * bound runs a handful of commands, not three at every crossing. A command that fails (exit code not 0, or cannot be
 * started), that outlives the timeout (it is killed, with its process group, {@link HookProcess}) or that finds its
 * log's queue full is reported in one line and never retried, so no event runs its command twice. The command's
 * standard output is discarded (it must not mix with {@code --json} on stdout); its standard error is predmon's.
 */
public final class CommandHooks implements AutoCloseable {

    static final int THREADS = 4;
    static final int PER_LOG = 16;
    /** The hold time of {@link AlarmHold} unless told otherwise. */
    public static final Duration HOLD = Duration.ofSeconds(5);

    private final String onWarning;
    private final String onViolation;
    private final String onRecovered;
    private final Duration timeout;
    private final Consumer<String> report;
    private final double bound;
    private final HookQueue queue = new HookQueue(THREADS, PER_LOG);
    private final AlarmHold hold;
    /** Every property by id, for the words in the environment. */
    private volatile Map<String, Property> properties = Map.of();

    /**
     * @param onWarning   command for each warning, or null
     * @param onViolation command for each violation, or null
     * @param timeout     how long a command may run before it is killed
     * @param report      receives one line per failure (watch prints it on stderr); called from the hooks' threads
     */
    public CommandHooks(String onWarning, String onViolation, Duration timeout, Consumer<String> report) {
        this(onWarning, onViolation, timeout, Double.NaN, report);
    }

    /**
     * As above, for a property violated below {@code bound}: values below it are rounded down in the environment, as
     * the page shows them ({@link HookEnvironment}).
     */
    public CommandHooks(String onWarning, String onViolation, Duration timeout, double bound, Consumer<String> report) {
        this(onWarning, onViolation, null, timeout, bound, report);
    }

    /**
     * As above, with {@code onRecovered} run for each recovery (a warning's or a violation's cause ended: the
     * property's alarm is over), or null.
     */
    public CommandHooks(String onWarning, String onViolation, String onRecovered, Duration timeout, double bound,
                        Consumer<String> report) {
        this(onWarning, onViolation, onRecovered, timeout, HOLD, bound, report);
    }

    /** As above, a recovery's command held for {@code hold} (zero: none, every event runs its command at once). */
    public CommandHooks(String onWarning, String onViolation, String onRecovered, Duration timeout, Duration hold,
                        double bound, Consumer<String> report) {
        if (timeout.isNegative() || timeout.isZero()) {
            throw new IllegalArgumentException("the hook timeout must be positive, got " + timeout);
        }
        this.onWarning = onWarning;
        this.onViolation = onViolation;
        this.onRecovered = onRecovered;
        this.timeout = timeout;
        this.report = report;
        this.bound = bound;
        this.hold = new AlarmHold(hold, report);
    }

    /**
     * Gives the hooks' environment each property's words ({@link HookEnvironment#of(String, MonitorEvent, double,
     * Map)}); returns this.
     */
    public CommandHooks describing(List<Property> all) {
        Map<String, Property> byId = new LinkedHashMap<>();
        all.forEach(p -> byId.put(p.id(), p));
        properties = Map.copyOf(byId);
        return this;
    }

    /** Queues the command for {@code sent}, if its event has one (a warning, a violation); returns at once. */
    public void event(LogEvent sent) {
        String log = sent.log();
        MonitorEvent event = sent.event();
        AlarmHold.Kind kind = event instanceof MonitorEvent.Warning ? AlarmHold.Kind.WARNING
                : event instanceof MonitorEvent.Violation ? AlarmHold.Kind.VIOLATION
                : event instanceof MonitorEvent.Recovered ? AlarmHold.Kind.RECOVERY : AlarmHold.Kind.NONE;
        if (kind == AlarmHold.Kind.NONE) {
            return;
        }
        String command = switch (kind) {
            case WARNING -> onWarning;
            case VIOLATION -> onViolation;
            default -> onRecovered;
        };
        // every alarm event goes through the hold, with a command or not: a recovery ends the robot's alarm
        Run run = command == null ? null
                : new Run(command, option(event), describe(log, event), HookEnvironment.of(log, event, bound, properties),
                sent.line());
        hold.event(log, property(event), run(event), kind, run == null ? () -> { } : () -> submit(log, run),
                run == null ? "" : run.option + ": " + run.what);
    }

    /** {@code log} is forgotten (deleted long ago): what the hold kept of its alarms goes. */
    public void forget(String log) {
        hold.forget(log);
    }

    private void submit(String log, Run run) {
        if (!queue.offer(log, run)) {
            report.accept(run.option + ": " + run.what + ": not run, " + PER_LOG + " commands of " + log
                    + " are already waiting");
        }
    }

    /**
     * Runs the recoveries still held, then lets running and queued commands finish, waiting at most the timeout (plus
     * a second); what is still queued then is reported as not run and what still runs is killed. An interrupt of the
     * caller (watch being stopped) does not cut this wait short; the interrupt status is kept.
     */
    @Override
    public void close() {
        boolean interrupted = Thread.interrupted();
        try {
            hold.close();
            queue.close(timeout.toMillis() + 1000);
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private static String property(MonitorEvent e) {
        return e instanceof MonitorEvent.Warning w ? w.property() : e instanceof MonitorEvent.Violation v
                ? v.property() : ((MonitorEvent.Recovered) e).property();
    }

    private static int run(MonitorEvent e) {
        return e instanceof MonitorEvent.Warning w ? w.run() : e instanceof MonitorEvent.Violation v
                ? v.run() : ((MonitorEvent.Recovered) e).run();
    }

    private static String option(MonitorEvent e) {
        return e instanceof MonitorEvent.Warning ? "--on-warning" : e instanceof MonitorEvent.Recovered
                ? "--on-recovered" : "--on-violation";
    }

    private static String describe(String log, MonitorEvent e) {
        long line = e instanceof MonitorEvent.Warning w ? w.line() : e instanceof MonitorEvent.Recovered r ? r.line()
                : ((MonitorEvent.Violation) e).line();
        return (e instanceof MonitorEvent.Warning ? "warning" : e instanceof MonitorEvent.Recovered ? "recovery"
                : "violation") + " of " + log + " line " + line;
    }

    /** The shell that runs a command line: {@code sh -c} (or {@code cmd /c} on Windows). */
    static List<String> shell(String command) {
        return System.getProperty("os.name", "").startsWith("Windows") ? List.of("cmd.exe", "/c", command)
                : List.of("/bin/sh", "-c", command);
    }

    /** One command for one event. */
    private final class Run implements HookQueue.Job {
        private final String command;
        private final String option;
        private final String what;
        private final Map<String, String> env;
        private final String json;

        Run(String command, String option, String what, Map<String, String> env, String json) {
            this.command = command;
            this.option = option;
            this.what = what;
            this.env = env;
            this.json = json;
        }

        @Override
        public void run() {
            HookProcess.Outcome outcome;
            try {
                outcome = HookProcess.run(command, env, json, timeout);
            } catch (InterruptedException e) {
                report.accept(option + ": " + what + ": killed, watch ended");
                return;
            }
            if (outcome instanceof HookProcess.NotStarted n) {
                report.accept(option + ": " + what + ": could not be started: " + n.why());
            } else if (outcome instanceof HookProcess.TimedOut) {
                report.accept(String.format(Locale.ROOT, "%s: %s: timed out after %s s, killed", option, what,
                        seconds(timeout)));
            } else if (outcome instanceof HookProcess.Exited x && x.code() != 0) {
                report.accept(option + ": " + what + ": failed with exit code " + x.code());
            }
        }

        @Override
        public void dropped() {
            report.accept(option + ": " + what + ": not run, watch ended");
        }
    }

    private static String seconds(Duration d) {
        double s = d.toMillis() / 1000.0;
        return s == Math.rint(s) ? Long.toString((long) s) : Double.toString(s);
    }
}
