package dev.predmon.cli;

import dev.predmon.hooks.CommandHooks;
import dev.predmon.live.Board;
import dev.predmon.live.Tile;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;

import java.io.PrintWriter;
import java.util.HashMap;
import java.util.Map;

/**
 * Where {@code watch}'s events go: each log's events to stdout through its own {@link EventPrinter} (each log has
 * its own warning, hence its own lead), tagged with the log when several are watched; parse problems to stderr;
 * to the live view's tile of the log, and warnings and violations to the hook commands, as JSON that always names
 * the log.
 */
final class WatchOutputs implements Fleet.Listener, AutoCloseable {

    private final PrintWriter out;
    private final PrintWriter err;
    private final boolean json;
    private final boolean eliminations;
    private final boolean several;
    private final Map<WatchedLog, Outlet> outlets = new HashMap<>();
    private final CommandHooks hooks;
    private final Board board;
    private String lastRescanFailure;

    /** Where one log's events go. */
    private record Outlet(EventPrinter printer, Tile tile) {
    }

    /**
     * @param several whether events must name their log (several logs, or a directory or glob)
     * @param hooks   the hook commands, or null; closed with this
     * @param board   the live view, or null
     */
    WatchOutputs(PrintWriter out, PrintWriter err, boolean json, boolean eliminations, boolean several,
                 CommandHooks hooks, Board board) {
        this.out = out;
        this.err = err;
        this.json = json;
        this.eliminations = eliminations;
        this.several = several;
        this.hooks = hooks;
        this.board = board;
    }

    @Override
    public void added(WatchedLog log) {
        outlets.put(log, new Outlet(new EventPrinter(out, json, eliminations, several ? log.name() : null),
                board == null ? null : board.tile(log.name())));
    }

    @Override
    public void event(WatchedLog log, MonitorEvent e) {
        Outlet o = outlets.get(log);
        o.printer().accept(e);
        boolean hook = hooks != null && (e instanceof MonitorEvent.Warning || e instanceof MonitorEvent.Violation);
        if (hook || o.tile() != null) {
            String tagged = EventPrinter.toJson(e, log.name());
            if (o.tile() != null) {
                board.event(o.tile(), e, tagged);
            }
            if (hook) {
                hooks.event(log.name(), e, tagged);
            }
        }
    }

    @Override
    public void record(WatchedLog log, LogRecord r) {
        Tile tile = outlets.get(log).tile();
        if (tile != null) {
            tile.record(r);
        }
    }

    @Override
    public void grew(WatchedLog log) {
        Tile tile = outlets.get(log).tile();
        if (tile != null) {
            board.grew(tile);
        }
    }

    @Override
    public void problem(WatchedLog log, ParseProblem p) {
        err.println(p.format(log.name()));
        err.flush();
    }

    @Override
    public void rescanFailed(java.io.IOException e) {
        String message = "predmon: looking for new logs: " + e;
        if (!message.equals(lastRescanFailure)) { // once, not every second
            err.println(message);
            err.flush();
            lastRescanFailure = message;
        }
    }

    @Override
    public void close() {
        if (hooks != null) {
            hooks.close();
        }
        out.flush();
    }
}
