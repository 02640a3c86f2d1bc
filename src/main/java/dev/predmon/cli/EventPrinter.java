package dev.predmon.cli;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.parse.Clock;

import java.io.PrintWriter;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Prints monitor events as they happen: one readable line each, or with {@code --json} one JSON object per
 * line ({@code {"event":"warning","time":...,"scenario":...,"battery":...}}), flushed at once so a pipe sees
 * each warning immediately.
 */
final class EventPrinter implements Consumer<MonitorEvent> {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final PrintWriter out;
    private final boolean json;
    private final boolean verbose;
    private final String log;
    private MonitorEvent.Warning warning;

    /** @param eliminations also print each model's elimination (JSON always does) */
    EventPrinter(PrintWriter out, boolean json, boolean eliminations) {
        this(out, json, eliminations, null);
    }

    /**
     * For one log of several: each event says which ({@code "log"} in JSON, a {@code log: } prefix in text).
     *
     * @param log the log's name, or null when only one log is watched
     */
    EventPrinter(PrintWriter out, boolean json, boolean eliminations, String log) {
        this.out = out;
        this.json = json;
        this.verbose = eliminations;
        this.log = log;
    }

    @Override
    public void accept(MonitorEvent e) {
        if (json) {
            out.println(toJson(e, log));
        } else {
            String text = toText(e);
            if (text != null) {
                out.println(log == null ? text : log + ": " + text);
            }
        }
        out.flush();
    }

    /** The JSON object of an event. */
    static String toJson(MonitorEvent e) {
        return toJson(e, null);
    }

    /** The JSON object of an event of {@code log} ({@code "log"} right after {@code "event"}), or untagged if null. */
    static String toJson(MonitorEvent e, String log) {
        Map<String, Object> o = new LinkedHashMap<>();
        if (e instanceof MonitorEvent.Warning w) {
            o.put("event", "warning");
            o.put("time", w.time());
            o.put("unit", w.clock().unit());
            o.put("line", w.line());
            o.put("run", w.run());
            o.put("scenario", w.scenarios().get(0));
            o.put("scenarios", w.scenarios());
            o.put("battery", w.battery());
            o.put("pairs", w.pairs());
        } else if (e instanceof MonitorEvent.Violation v) {
            o.put("event", "violation");
            o.put("time", v.time());
            o.put("unit", v.clock().unit());
            o.put("line", v.line());
            o.put("run", v.run());
            o.put("property", v.property());
            o.put("battery", v.value());
            o.put("before", v.before());
        } else if (e instanceof MonitorEvent.Eliminated x) {
            o.put("event", "eliminated");
            o.put("time", x.time());
            o.put("unit", x.clock().unit());
            o.put("line", x.line());
            o.put("run", x.run());
            o.put("model", x.model());
            o.put("scenario", x.scenario());
            o.put("faulty", x.faulty());
            o.put("reason", x.reason());
        } else if (e instanceof MonitorEvent.NoMatch n) {
            o.put("event", "no-match");
            o.put("time", n.time());
            o.put("unit", n.clock().unit());
            o.put("line", n.line());
            o.put("run", n.run());
        } else if (e instanceof MonitorEvent.RunStarted r) {
            o.put("event", "run");
            o.put("run", r.run());
            o.put("time", r.time());
            o.put("unit", r.clock().unit());
            o.put("line", r.line());
        } else if (e instanceof MonitorEvent.Restarted r) {
            o.put("event", "restarted");
            o.put("reason", r.reason());
        }
        return write(log == null ? o : tagged(o, log));
    }

    /** {@code o} with {@code "log"} after its {@code "event"}. */
    static Map<String, Object> tagged(Map<String, Object> o, String log) {
        Map<String, Object> t = new LinkedHashMap<>();
        o.forEach((k, v) -> {
            t.put(k, v);
            if (k.equals("event")) {
                t.put("log", log);
            }
        });
        return t;
    }

    static String write(Map<String, Object> o) {
        try {
            return JSON.writeValueAsString(o);
        } catch (JsonProcessingException ex) {
            throw new IllegalStateException("maps of plain values always serialise", ex);
        }
    }

    String toText(MonitorEvent e) {
        if (e instanceof MonitorEvent.Warning w) {
            warning = w;
            return String.format(Locale.ROOT, "%s line %d: WARNING: the run can only be faulty scenario %s "
                    + "(every nominal model eliminated); battery %s", at(w.time(), w.clock()), w.line(),
                    String.join(", ", w.scenarios()), battery(w.battery()));
        }
        if (e instanceof MonitorEvent.Violation v) {
            String lead = warning == null ? "no warning came before it"
                    : String.format(Locale.ROOT, "lead of the warning: %s, battery %s at the warning vs %s now",
                    span(v.time() - warning.time(), v.clock()), battery(warning.battery()), battery(v.value()));
            return String.format(Locale.ROOT, "%s line %d: VIOLATION of '%s': %s; %s", at(v.time(), v.clock()), v.line(),
                    v.property(), battery(v.value()), lead);
        }
        if (e instanceof MonitorEvent.Eliminated x) {
            return verbose ? String.format(Locale.ROOT, "%s line %d: model %s (%s) eliminated: %s", at(x.time(), x.clock()),
                    x.line(), x.model(), x.faulty() ? "faulty" : "nominal", x.reason()) : null;
        }
        if (e instanceof MonitorEvent.NoMatch n) {
            return String.format(Locale.ROOT, "%s line %d: no learned scenario matches this run any more",
                    at(n.time(), n.clock()), n.line());
        }
        if (e instanceof MonitorEvent.RunStarted r) {
            warning = null;
            return String.format(Locale.ROOT, "%s line %d: run %d begins: every model starts over",
                    at(r.time(), r.clock()), r.line(), r.run());
        }
        if (e instanceof MonitorEvent.Restarted r) {
            warning = null;
            return "log " + r.reason() + ": monitoring starts over";
        }
        return null;
    }

    /** When an event happened: {@code t=71.819} in seconds, {@code tick 188} in a log without time stamps. */
    static String at(double time, Clock clock) {
        return clock == Clock.TICKS ? String.format(Locale.ROOT, "tick %.0f", time)
                : String.format(Locale.ROOT, "t=%.3f", time);
    }

    /** A duration with its unit: {@code 5.026 s} or {@code 48 ticks}. */
    static String span(double amount, Clock clock) {
        return clock == Clock.TICKS ? String.format(Locale.ROOT, "%.0f ticks", amount)
                : String.format(Locale.ROOT, "%.3f s", amount);
    }

    private static String battery(Double b) {
        return b == null ? "unknown" : String.format(Locale.ROOT, "%.2f", b);
    }
}
