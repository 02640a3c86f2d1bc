package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.hooks.CommandHooks;
import dev.predmon.live.Board;
import dev.predmon.live.Tile;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.TickSeconds;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;
import dev.predmon.pipeline.Evidence;
import dev.predmon.pipeline.UnmappedMessages;

import java.io.IOException;
import java.io.PrintWriter;
import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Predicate;

/**
 * Where {@code watch}'s events go: each log's events to stdout through its own {@link EventPrinter} (each log has
 * its own warning, hence its own lead), tagged with the log when several are watched; parse problems to stderr
 * (with {@code --no-follow} held until the log is known to hold something to judge, so that a file that is no log
 * gets one line, not a list); interface messages no rule maps, at their first sighting while following; to the
 * live view's tile of the log, and warnings and violations to the hook commands, as JSON that always names the log
 * (while following, only those after the logs' history was read: a hook is for what happens now); a line on stderr
 * when a log is found and followed, and the heartbeat lines.
 */
final class WatchOutputs implements Fleet.Listener, AutoCloseable {

    private final PrintWriter out;
    private final PrintWriter err;
    private final boolean json;
    private final boolean eliminations;
    private final boolean several;
    private final boolean noFollow;
    private final Abstraction abstraction;
    private final Predicate<Path> found;
    private final Map<WatchedLog, Outlet> outlets = new LinkedHashMap<>();
    private final CommandHooks hooks;
    private final Board board;
    private String lastRescanFailure;
    private String notALog;
    /**
     * Whether events are news, to be sent to the hooks: with {@code --no-follow} always (the file is judged as a
     * whole), while following only once the logs' history has been read ({@link #caughtUp}).
     */
    private boolean live;
    private final boolean timestamps;
    private final long heartbeatNanos;
    private final TickSeconds ticks;
    /** Whether following has begun, so that the next {@link #beat} is a heartbeat. */
    private boolean beating;

    /** Where one log's events go, and what is known of its evidence so far. */
    private static final class Outlet {
        final EventPrinter printer;
        final Tile tile;
        final ProblemLines problems = new ProblemLines();
        /** Something recognisable arrived, or the notice that nothing did was given. */
        boolean settled;
        /** When the log's first line was read ({@link System#nanoTime()}), 0 before. */
        long firstLineNanos;
        /** The runs that began where the log was truncated or replaced, with which of the two. */
        final Map<Integer, String> restarts = new HashMap<>();
        /** The commands of unmapped messages said at their first sighting. */
        final Set<String> commandsSeen = new HashSet<>();
        /** Whether the line that the file is followed was given. */
        boolean announced;

        Outlet(EventPrinter printer, Tile tile) {
            this.printer = printer;
            this.tile = tile;
        }
    }

    /**
     * @param several     whether events must name their log (several logs, or a directory or glob)
     * @param hooks       the hook commands, or null; closed with this
     * @param board       the live view, or null
     * @param abstraction the abstraction logs are read with, for messages about logs it does not fit
     * @param found       whether a log was found under a directory or glob rather than named
     */
    WatchOutputs(PrintWriter out, PrintWriter err, boolean json, boolean eliminations, boolean several, boolean noFollow,
                 CommandHooks hooks, Board board, Abstraction abstraction, Predicate<Path> found) {
        this(out, err, json, eliminations, several, noFollow, hooks, board, abstraction, found, false, 0,
                TickSeconds.NONE);
    }

    /**
     * As above, and
     *
     * @param timestamps     start every text line of events with the wall-clock time
     * @param heartbeatNanos the pause between two heartbeat lines while following; 0 for none
     * @param ticks          how long a tick lasts, so that logs counted in ticks report seconds
     */
    WatchOutputs(PrintWriter out, PrintWriter err, boolean json, boolean eliminations, boolean several, boolean noFollow,
                 CommandHooks hooks, Board board, Abstraction abstraction, Predicate<Path> found, boolean timestamps,
                 long heartbeatNanos, TickSeconds ticks) {
        this.out = out;
        this.err = err;
        this.json = json;
        this.eliminations = eliminations;
        this.several = several;
        this.noFollow = noFollow;
        this.hooks = hooks;
        this.board = board;
        this.abstraction = abstraction;
        this.found = found;
        this.live = noFollow;
        this.timestamps = timestamps;
        this.heartbeatNanos = heartbeatNanos;
        this.ticks = ticks;
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
        Outlet o = new Outlet(new EventPrinter(out, json, eliminations, several ? log.name() : null, timestamps),
                board == null ? null : board.tile(log.name()));
        outlets.put(log, o);
        log.monitor().countTicksAs(ticks);
        // A log named is said once what it held at the start is read; of those found in a directory or by a glob,
        // only the ones that appear while watching, once they hold a record (not every file of the directory at the
        // start, not notes beside the logs).
        o.announced = noFollow || (found.test(log.path()) && !live);
    }

    /** Says on stderr, once per log, that its file is found and followed. */
    private void announce(Outlet o, String what) {
        o.announced = true;
        err.println(Terminal.line("predmon: " + what));
        err.flush();
    }

    /** Every {@code --heartbeat} while following: each log's line, run and latest forecast on stdout. */
    @Override
    public long beat() {
        if (heartbeatNanos <= 0) {
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
        return heartbeatNanos;
    }

    @Override
    public void event(WatchedLog log, MonitorEvent e) {
        if (e instanceof MonitorEvent.Unmapped u) {
            firstSighting(log, u);
            return;
        }
        Outlet o = outlets.get(log);
        if (e instanceof MonitorEvent.Restarted r) {
            o.restarts.put(log.monitor().run(), r.reason()); // the monitor has begun the run that follows it
        }
        Instant at = Instant.now();
        o.printer.accept(e, at);
        boolean hook = hooks != null && live
                && (e instanceof MonitorEvent.Warning || e instanceof MonitorEvent.Violation
                || e instanceof MonitorEvent.Recovered);
        if (hook || o.tile != null) {
            String tagged = EventPrinter.toJson(e, log.name(), at);
            if (o.tile != null) {
                board.event(o.tile, e, tagged);
            }
            if (hook) {
                hooks.event(log.name(), e, tagged);
            }
        }
    }

    /**
     * While following, the first message of each command no rule maps, with its line, for at most
     * {@value UnmappedMessages#MAX_LINES} commands (one line per pose value would bury everything else); with
     * {@code --no-follow} the totals by command at the end say it all.
     */
    private void firstSighting(WatchedLog log, MonitorEvent.Unmapped u) {
        Outlet o = outlets.get(log);
        if (noFollow || o.commandsSeen.size() > UnmappedMessages.MAX_LINES
                || !o.commandsSeen.add(UnmappedMessages.command(u.message()))) {
            return;
        }
        err.println(Terminal.line(log.name() + ":" + u.line() + ": warning: " + (o.commandsSeen.size()
                > UnmappedMessages.MAX_LINES ? "more commands no abstraction rule maps; the totals come at the stop"
                : "interface message no abstraction rule maps: " + u.message() + " (first of its command; the "
                + "totals come at the stop)")));
        err.flush();
    }

    @Override
    public void record(WatchedLog log, LogRecord r) {
        Tile tile = outlets.get(log).tile;
        if (tile != null) {
            tile.record(ticks.record(r));
            tile.properties(log.monitor().properties());
        }
    }

    /** After the first lines of a followed log, says once if nothing recognisable has arrived. */
    @Override
    public void grew(WatchedLog log) {
        Outlet o = outlets.get(log);
        if (o.tile != null) {
            board.grew(o.tile);
        }
        if (live && !o.announced && (!found.test(log.path()) || log.monitor().records() > 0)) {
            announce(o, log.name() + " appeared; following it");
        }
        if (!noFollow && !o.settled) {
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
            if (!noFollow && !o.settled && o.firstLineNanos != 0) {
                notALog(log, o);
            }
        });
    }

    /**
     * Whether {@code log} is not a monitor log ({@link Evidence#notALog}): said once on stderr and on its tile; a
     * single log's watch then stops, to exit 3 ({@link #notALog()}).
     */
    private boolean notALog(WatchedLog log, Outlet o) {
        long millis = o.firstLineNanos == 0 ? 0 : (System.nanoTime() - o.firstLineNanos) / 1_000_000;
        Optional<String> not = evidence(log).notALog(millis);
        if (not.isEmpty()) {
            return false;
        }
        noVerdict(log, o, not.get());
        o.settled = true;
        if (!several) {
            notALog = not.get();
            Thread.currentThread().interrupt(); // watch stops here: see WatchCommand
        }
        return true;
    }

    /** Says once on stderr why {@code log} gets no verdict, and shows it on its tile. */
    private void noVerdict(WatchedLog log, Outlet o, String why) {
        err.println("predmon: " + Terminal.line(why));
        err.flush();
        if (o.tile != null) {
            String path = log.path().toString();
            o.tile.noVerdict(why.startsWith(path + ": ") ? why.substring(path.length() + 2) : why);
        }
    }

    /** Why a single log being followed was found not to be a monitor log, if it was: watch stops and exits 3. */
    Optional<String> notALog() {
        return Optional.ofNullable(notALog);
    }

    @Override
    public void problem(WatchedLog log, ParseProblem p) {
        outlets.get(log).problems.add(err, log.name(), p, noFollow);
    }

    /** With {@code --no-follow}: prints the problems held for {@code log}. */
    void flushProblems(WatchedLog log) {
        outlets.get(log).problems.flush(err, log.name());
    }

    /**
     * Whether {@code log} is a file found beside the logs of a directory or glob that holds no monitor record (notes,
     * a core dump): not a log that failed, so it is skipped silently when another log was judged.
     */
    boolean besideTheLogs(WatchedLog log) {
        return found.test(log.path()) && log.monitor().records() == 0;
    }

    /** How run {@code run} of {@code log} began, when it began where the log was truncated or replaced. */
    Optional<String> restartBefore(WatchedLog log, int run) {
        return Optional.ofNullable(outlets.get(log).restarts.get(run));
    }

    /** What {@code log} has given so far to judge it by. */
    Evidence evidence(WatchedLog log) {
        PredictiveMonitor m = log.monitor();
        long pairs = m.summary().pairs();
        return new Evidence(log.path(), log.watcher()::lines, m.records(), m.interfaceRecords(), pairs, m.unmapped(),
                abstraction, outlets.get(log).problems.first(), m.pipeline().span());
    }

    @Override
    public void rescanFailed(IOException e) {
        String message = "predmon: looking for new logs: " + Terminal.line(e.getMessage());
        if (!message.equals(lastRescanFailure)) { // once, not every second
            err.println(message);
            err.flush();
            lastRescanFailure = message;
        }
    }

    /** One line on stderr: what cannot be notified, why, and that it is polled instead, how often. */
    @Override
    public void unnotified(Path dir, String why, long pauseNanos) {
        String every = BigDecimal.valueOf(pauseNanos, 6).stripTrailingZeros().toPlainString() + " ms";
        err.println(Terminal.line("predmon: file-change notification unavailable" + (dir == null ? "" : " for " + dir)
                + " (" + why + "); polling " + (dir == null ? "every log" : "its logs") + " every " + every));
        err.flush();
    }

    /** One line on stderr about a log the fleet goes on watching (something at its path that is no file, ...). */
    @Override
    public void notice(String line) {
        err.println("predmon: " + Terminal.line(line));
        err.flush();
    }

    @Override
    public void close() {
        if (hooks != null) {
            hooks.close();
        }
        out.flush();
    }
}
