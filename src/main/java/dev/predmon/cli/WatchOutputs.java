package dev.predmon.cli;

import dev.predmon.hooks.CommandHooks;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.parse.ParseProblem;

import java.io.PrintWriter;
import java.util.HashMap;
import java.util.Map;

/**
 * Where {@code watch}'s events go: each log's events to stdout through its own {@link EventPrinter} (each log has
 * its own warning, hence its own lead), tagged with the log when several are watched; parse problems to stderr;
 * warnings and violations to the hook commands, as JSON that always names the log.
 */
final class WatchOutputs implements Fleet.Listener, AutoCloseable {

    private final PrintWriter out;
    private final PrintWriter err;
    private final boolean json;
    private final boolean eliminations;
    private final boolean several;
    private final Map<WatchedLog, EventPrinter> printers = new HashMap<>();
    private final CommandHooks hooks;

    /**
     * @param several whether events must name their log (several logs, or a directory or glob)
     * @param hooks   the hook commands, or null; closed with this
     */
    WatchOutputs(PrintWriter out, PrintWriter err, boolean json, boolean eliminations, boolean several,
                 CommandHooks hooks) {
        this.out = out;
        this.err = err;
        this.json = json;
        this.eliminations = eliminations;
        this.several = several;
        this.hooks = hooks;
    }

    @Override
    public void added(WatchedLog log) {
        printers.put(log, new EventPrinter(out, json, eliminations, several ? log.name() : null));
    }

    @Override
    public void event(WatchedLog log, MonitorEvent e) {
        printers.get(log).accept(e);
        if (hooks != null && (e instanceof MonitorEvent.Warning || e instanceof MonitorEvent.Violation)) {
            hooks.event(log.name(), e, EventPrinter.toJson(e, log.name()));
        }
    }

    @Override
    public void problem(WatchedLog log, ParseProblem p) {
        err.println(p.format(log.name()));
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
