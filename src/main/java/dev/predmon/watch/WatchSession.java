package dev.predmon.watch;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.event.LogEvent;
import dev.predmon.hooks.CommandHooks;
import dev.predmon.live.Board;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.FleetListener;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;
import dev.predmon.pipeline.Evidence;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * A watch session: follows logs into monitors (as the {@link Fleet}'s listener) and sends each event to stdout (each
 * log through its own {@link EventPrinter}: each log has its own warning, hence its own lead; tagged with the log when
 * several are watched), to the live view's tile of the log, and warnings and violations to the hook commands, the
 * last two as one {@link LogEvent} that names the log (hooks only for what happens after the logs' history was read:
 * a hook is for what happens now). Parse problems go to stderr (with {@code --no-follow} held until the log is known
 * to hold something to judge, so that a file that is no log gets one line, not a list), with the other
 * {@link Notices}, and the heartbeat lines to stdout. At the end, {@link #finish} gives each log its summary and the
 * session its exit code ({@link Verdicts}).
 */
public final class WatchSession implements FleetListener, AutoCloseable {

    private final PrintWriter out;
    private final PrintWriter err;
    private final WatchSettings settings;
    private final Abstraction abstraction;
    private final Predicate<Path> found;
    private final Map<WatchedLog, LogOutlet> outlets = new LinkedHashMap<>();
    private final CommandHooks hooks;
    private final Board board;
    private final Notices notices;
    private String notALog;
    /** The exit codes of the logs forgotten once deleted, each judged when it was forgotten. */
    private final List<Integer> forgottenCodes = new ArrayList<>();
    /**
     * Whether events are news, to be sent to the hooks: with {@code --no-follow} always (the file is judged as a
     * whole), while following only once the logs' history has been read ({@link #caughtUp}).
     */
    private boolean live;
    /** Whether following has begun, so that the next {@link #beat} is a heartbeat. */
    private boolean beating;

    /**
     * @param hooks       the hook commands, or null; closed with this
     * @param board       the live view, or null
     * @param abstraction the abstraction logs are read with, for messages about logs it does not fit
     * @param found       whether a log was found under a directory or glob rather than named
     */
    public WatchSession(PrintWriter out, PrintWriter err, WatchSettings settings, CommandHooks hooks, Board board,
                        Abstraction abstraction, Predicate<Path> found) {
        this.out = out;
        this.err = err;
        this.settings = settings;
        this.hooks = hooks;
        this.board = board;
        this.abstraction = abstraction;
        this.found = found;
        this.live = settings.noFollow();
        this.notices = new Notices(err);
    }

    /**
     * The history of the logs is read: from now on warnings and violations run the hooks, and each log named that
     * exists is said to be followed.
     */
    @Override
    public void caughtUp() {
        live = true;
        outlets.forEach((log, o) -> {
            if (!o.announced && Files.exists(log.path())) {
                announce(o, "following " + log.name());
            }
        });
    }

    @Override
    public void added(WatchedLog log) {
        LogOutlet o = new LogOutlet(new EventPrinter(out, settings.json(), settings.eliminations(),
                settings.several() ? log.name() : null, settings.stamp())
                .forecastProperty(log.monitor().forecastProperty().orElse(null)),
                board == null ? null : board.tile(log.name()));
        outlets.put(log, o);
        log.monitor().countTicksAs(settings.ticks());
        // A log named is said once what it held at the start is read; of those found in a directory or by a glob,
        // only the ones that appear while watching, once they hold a record (not every file of the directory at the
        // start, not notes beside the logs).
        o.announced = settings.noFollow() || (found.test(log.path()) && !live);
    }

    /**
     * A log deleted long ago leaves: its summary is printed now ({@code stop} {@code deleted}) and its exit code kept
     * for the end; its tile leaves the page and {@code /metrics}. A deleted file that gave nothing to judge leaves
     * without a word.
     */
    @Override
    public void forgotten(WatchedLog log) {
        LogOutlet o = outlets.get(log);
        if (o == null) {
            return;
        }
        try {
            new Verdicts(this, new Summary(out, err, settings), settings).forgotten(log).ifPresent(forgottenCodes::add);
        } finally {
            outlets.remove(log);
            if (board != null && o.tile != null) {
                board.forget(o.tile);
            }
            if (hooks != null) {
                hooks.forget(log.name());
            }
        }
    }

    private void announce(LogOutlet o, String what) {
        o.announced = true;
        notices.say(what);
    }

    /** Every {@code --heartbeat} while following: each log's line, run and latest forecast on stdout. */
    @Override
    public long beat() {
        if (settings.heartbeatNanos() <= 0) {
            return Long.MAX_VALUE;
        }
        if (beating) {
            Instant at = Instant.now();
            outlets.forEach((log, o) -> {
                PredictiveMonitor m = log.monitor();
                o.printer.heartbeat(log.watcher().lines(), m.run(), m.records(), m.forecast().orElse(null),
                        Files.exists(log.path()), at);
            });
        }
        beating = true;
        return settings.heartbeatNanos();
    }

    @Override
    public void event(WatchedLog log, MonitorEvent e) {
        LogOutlet o = outlets.get(log);
        if (e instanceof MonitorEvent.Unmapped u) {
            if (!settings.noFollow() && o.firstOfItsCommand(u.message())) {
                notices.unmapped(log.name(), u.line(), u.message(), o.commandsSeen());
            }
            return;
        }
        if (e instanceof MonitorEvent.Restarted r) {
            o.restarts.put(log.monitor().run(), r.reason()); // the monitor has begun the run that follows it
        }
        Instant at = Instant.now();
        o.printer.accept(e, at);
        boolean hook = hooks != null && live
                && (e instanceof MonitorEvent.Warning || e instanceof MonitorEvent.Violation
                || e instanceof MonitorEvent.Recovered);
        if (hook || o.tile != null) {
            LogEvent sent = LogEvent.of(log.name(), e, at);
            if (o.tile != null) {
                board.event(o.tile, sent);
            }
            if (hook) {
                hooks.event(sent);
            }
        }
    }

    @Override
    public void record(WatchedLog log, LogRecord r) {
        LogOutlet o = outlets.get(log);
        if (o.tile != null) {
            o.tile.record(settings.ticks().record(r), log.monitor().judged());
            o.tile.properties(log.monitor().properties());
        }
    }

    /** After the first lines of a followed log, says once if nothing recognisable has arrived. */
    @Override
    public void grew(WatchedLog log) {
        LogOutlet o = outlets.get(log);
        if (o.tile != null) {
            board.grew(o.tile);
        }
        if (live && !o.announced && (!found.test(log.path()) || log.monitor().records() > 0)) {
            announce(o, log.name() + " appeared; following it");
        }
        if (!settings.noFollow() && !o.settled) {
            if (o.firstLineNanos == 0 && log.watcher().lines() > 0) {
                o.firstLineNanos = System.nanoTime();
            }
            // A file beside the logs of a directory that is not a log is said once it is known; what else is missing
            // in it is said at the stop, and only if no log was judged.
            if (!notALog(log, o) && !besideTheLogs(log)) {
                Evidence evidence = evidence(log);
                Optional<String> notice = evidence.earlyNotice();
                notice.ifPresent(n -> noVerdict(log, o, n));
                o.settled = notice.isPresent() || evidence.recognised();
            }
        }
    }

    /** About once a second: a file that had lines for a while and no monitor record is not a monitor log. */
    @Override
    public void pulse() {
        outlets.forEach((log, o) -> {
            if (!settings.noFollow() && !o.settled && o.firstLineNanos != 0) {
                notALog(log, o);
            }
        });
    }

    /**
     * Whether {@code log} is not a monitor log ({@link Evidence#notALog}): said once on stderr and on its tile; a
     * single log's watch then stops, to exit 3 ({@link #finish}).
     */
    private boolean notALog(WatchedLog log, LogOutlet o) {
        long millis = o.firstLineNanos == 0 ? 0 : (System.nanoTime() - o.firstLineNanos) / 1_000_000;
        Evidence evidence = evidence(log);
        long yarp = log.watcher().yarpLines();
        Optional<String> not = evidence.notALog(millis, yarp);
        if (not.isEmpty()) {
            if (!o.toldPreamble) { // a monitor started before the robot: said once, and followed on
                evidence.preamble(millis, yarp).ifPresent(p -> {
                    o.toldPreamble = true;
                    notices.say(p);
                });
            }
            return false;
        }
        noVerdict(log, o, not.get());
        o.settled = true;
        if (!settings.several()) {
            notALog = not.get();
            Thread.currentThread().interrupt(); // the watch stops here, and finish says 3
        }
        return true;
    }

    /** Says once on stderr why {@code log} gets no verdict, and shows it on its tile. */
    private void noVerdict(WatchedLog log, LogOutlet o, String why) {
        notices.say(why);
        if (o.tile != null) {
            String path = log.path().toString();
            o.tile.noVerdict(why.startsWith(path + ": ") ? why.substring(path.length() + 2) : why);
        }
    }

    @Override
    public void problem(WatchedLog log, ParseProblem p) {
        outlets.get(log).problems.add(err, log.name(), p, settings.noFollow());
    }

    /**
     * Whether {@code log} is a file found beside the logs of a directory or glob that holds no monitor record (notes,
     * a core dump): not a log that failed, so it is skipped silently when another log was judged.
     */
    boolean besideTheLogs(WatchedLog log) {
        return found.test(log.path()) && log.monitor().records() == 0;
    }

    /** What {@code log} has given so far to judge it by. */
    Evidence evidence(WatchedLog log) {
        PredictiveMonitor m = log.monitor();
        return new Evidence(log.path(), log.watcher()::lines, m.records(), m.interfaceRecords(), m.summary().pairs(),
                m.unmapped(), abstraction, outlets.get(log).problems.first(), m.pipeline().span());
    }

    /**
     * The end of the watch ({@code stop}: {@code end-of-file}, the signal, or {@code interrupted}): each log's summary
     * on stdout and what it lacked on stderr, and the exit code ({@link Verdicts}).
     *
     * @throws BadInputException when the one log watched gets no verdict, with why
     */
    public int finish(Fleet fleet, String stop) throws BadInputException {
        if (!settings.noFollow() && notALog != null) {
            return ExitRule.BAD_INPUT; // said on stderr when it was found
        }
        if (forgottenCodes.isEmpty()) {
            return new Verdicts(this, new Summary(out, err, settings), settings).of(fleet.logs(), stop);
        }
        List<Integer> codes = new ArrayList<>(forgottenCodes);
        if (!fleet.logs().isEmpty()) {
            codes.add(new Verdicts(this, new Summary(out, err, settings), settings).of(fleet.logs(), stop));
        }
        return ExitRule.ofLogs(codes);
    }

    /** With {@code --no-follow}: prints the problems held for {@code log}. */
    void flushProblems(WatchedLog log) {
        outlets.get(log).problems.flush(err, log.name());
    }

    /** How run {@code run} of {@code log} began, when it began where the log was truncated or replaced. */
    Optional<String> restartBefore(WatchedLog log, int run) {
        return Optional.ofNullable(outlets.get(log).restarts.get(run));
    }

    @Override
    public void rescanFailed(IOException e) {
        notices.rescanFailed(e);
    }

    @Override
    public void unnotified(Path dir, String why, long pauseNanos) {
        notices.unnotified(dir, why, pauseNanos);
    }

    /** One line on stderr about a log the fleet goes on watching (something at its path that is no file, ...). */
    @Override
    public void notice(String line) {
        notices.say(line);
    }

    @Override
    public void close() {
        if (hooks != null) {
            hooks.close();
        }
        out.flush();
    }
}
