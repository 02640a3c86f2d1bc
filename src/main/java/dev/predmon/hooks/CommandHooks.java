package dev.predmon.hooks;

import dev.predmon.event.LogEvent;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.property.Property;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

/**
 * Delivers warnings and violations to the robot: {@code --on-warning CMD} and {@code --on-violation CMD} run a shell
 * command for each such event, and {@code --on-recovered CMD} for each recovery, so that an alarm raised on the robot
 * ends when its cause ends, with the event's JSON (one line) on its standard input and its main fields in
 * environment variables ({@link HookEnvironment}). This is the thesis's future work made possible: the deliberation
 * layer hears of the predicted failure while a recovery action can still help.
 *
 * <p>The monitor is never held up: {@link #event} only queues the command. At most {@value #THREADS} commands run at
 * once, started in event order; at most {@value #QUEUE} wait. A command that fails (exit code not 0, or cannot be
 * started), that outlives the timeout (it is killed, with its children) or that finds the queue full is reported in
 * one line and never retried, so no event runs its command twice. The command's standard output is discarded (it
 * must not mix with {@code --json} on stdout); its standard error is predmon's.
 */
public final class CommandHooks implements AutoCloseable {

    static final int THREADS = 4;
    static final int QUEUE = 64;

    private final String onWarning;
    private final String onViolation;
    private final String onRecovered;
    private final Duration timeout;
    private final Consumer<String> report;
    private final double bound;
    /** Every property by id, for the words in the environment. */
    private volatile Map<String, Property> properties = Map.of();
    private final ThreadPoolExecutor pool;

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
        if (timeout.isNegative() || timeout.isZero()) {
            throw new IllegalArgumentException("the hook timeout must be positive, got " + timeout);
        }
        this.onWarning = onWarning;
        this.onViolation = onViolation;
        this.onRecovered = onRecovered;
        this.timeout = timeout;
        this.report = report;
        this.bound = bound;
        AtomicInteger n = new AtomicInteger();
        this.pool = new ThreadPoolExecutor(THREADS, THREADS, 30, TimeUnit.SECONDS, new ArrayBlockingQueue<>(QUEUE),
                r -> {
                    Thread t = new Thread(r, "predmon-hook-" + n.incrementAndGet());
                    t.setDaemon(true);
                    return t;
                });
        pool.allowCoreThreadTimeOut(true);
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
        String command = event instanceof MonitorEvent.Warning ? onWarning
                : event instanceof MonitorEvent.Violation ? onViolation
                : event instanceof MonitorEvent.Recovered ? onRecovered : null;
        if (command == null) {
            return;
        }
        Run run = new Run(command, option(event), describe(log, event), HookEnvironment.of(log, event, bound, properties),
                sent.line());
        try {
            pool.execute(run);
        } catch (RejectedExecutionException full) {
            report.accept(run.option + ": " + run.what + ": not run, " + QUEUE + " commands are already waiting");
        }
    }

    /**
     * Lets running and queued commands finish, waiting at most the timeout (plus a second); what is still queued
     * then is reported as not run and what still runs is killed. An interrupt of the caller (watch being stopped)
     * does not cut this wait short; the interrupt status is kept.
     */
    @Override
    public void close() {
        boolean interrupted = Thread.interrupted();
        try {
            pool.shutdown();
            if (!awaitQuietly(timeout.toMillis() + 1000)) {
                List<Runnable> dropped = pool.shutdownNow();
                for (Runnable r : dropped) {
                    Run run = (Run) r;
                    report.accept(run.option + ": " + run.what + ": not run, watch ended");
                }
                awaitQuietly(2000);
            }
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private boolean awaitQuietly(long millis) {
        try {
            return pool.awaitTermination(millis, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            return false;
        }
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
    private final class Run implements Runnable {
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
            ProcessBuilder pb = new ProcessBuilder(shell(command));
            pb.environment().putAll(env);
            pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
            pb.redirectError(ProcessBuilder.Redirect.INHERIT);
            Process p;
            try {
                p = pb.start();
            } catch (IOException e) {
                report.accept(option + ": " + what + ": could not be started: " + e.getMessage());
                return;
            }
            try (OutputStream in = p.getOutputStream()) {
                in.write((json + "\n").getBytes(StandardCharsets.UTF_8));
            } catch (IOException e) {
                // The command ended or closed its input without reading it all: it need not read it.
            }
            try {
                if (!p.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
                    kill(p);
                    report.accept(String.format(Locale.ROOT, "%s: %s: timed out after %s s, killed", option, what,
                            seconds(timeout)));
                    return;
                }
            } catch (InterruptedException e) {
                kill(p);
                report.accept(option + ": " + what + ": killed, watch ended");
                return;
            }
            if (p.exitValue() != 0) {
                report.accept(option + ": " + what + ": failed with exit code " + p.exitValue());
            }
        }
    }

    /** Kills a command and whatever it started (a shell's children would otherwise live on). */
    private static void kill(Process p) {
        // The shell first, then what it started: a shell that outlives its children prints "Killed" for each on
        // watch's stderr, beside the report line that already says so.
        List<ProcessHandle> children = p.descendants().toList();
        p.destroyForcibly();
        children.forEach(ProcessHandle::destroyForcibly);
    }

    private static String seconds(Duration d) {
        double s = d.toMillis() / 1000.0;
        return s == Math.rint(s) ? Long.toString((long) s) : Double.toString(s);
    }
}
