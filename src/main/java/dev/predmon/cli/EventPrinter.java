package dev.predmon.cli;

import dev.predmon.monitor.MonitorEvent;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * Prints monitor events as they happen: one readable line each, or with {@code --json} one JSON object per
 * line ({@code {"event":"warning","time":...,"scenario":...,"battery":...}}), flushed at once so a pipe sees
 * each warning immediately.
 */
final class EventPrinter implements Consumer<MonitorEvent> {

    private final PrintWriter out;
    private final boolean json;
    private final boolean verbose;
    private MonitorEvent.Warning warning;

    /** @param eliminations also print each model's elimination (JSON always does) */
    EventPrinter(PrintWriter out, boolean json, boolean eliminations) {
        this.out = out;
        this.json = json;
        this.verbose = eliminations;
    }

    @Override
    public void accept(MonitorEvent e) {
        if (e instanceof MonitorEvent.Unmapped) {
            return; // the caller reports these with the parse problems
        }
        if (json) {
            out.println(toJson(e));
        } else {
            String text = toText(e);
            if (text != null) {
                out.println(text);
            }
        }
        out.flush();
    }

    /** The JSON object of an event ({@link MonitorEvent.Unmapped} is not one: it goes to stderr with the problems). */
    static String toJson(MonitorEvent e) {
        Object o;
        if (e instanceof MonitorEvent.Warning w) {
            o = new WarningJson("warning", w.time(), w.line(), w.scenarios().get(0), w.scenarios(), w.battery(), w.pairs());
        } else if (e instanceof MonitorEvent.Violation v) {
            o = new ViolationJson("violation", v.time(), v.line(), v.property(), v.value());
        } else if (e instanceof MonitorEvent.Eliminated x) {
            o = new EliminatedJson("eliminated", x.time(), x.line(), x.model(), x.scenario(), x.faulty(), x.reason());
        } else if (e instanceof MonitorEvent.NoMatch n) {
            o = new NoMatchJson("no-match", n.time(), n.line());
        } else if (e instanceof MonitorEvent.Restarted r) {
            o = new RestartedJson("restarted", r.reason());
        } else {
            throw new IllegalArgumentException("not printed as a JSON event: " + e);
        }
        return Json.line(o);
    }

    record WarningJson(String event, double time, long line, String scenario, List<String> scenarios, Double battery,
                       long pairs) {
    }

    record ViolationJson(String event, double time, long line, String property, double battery) {
    }

    record EliminatedJson(String event, double time, long line, String model, String scenario, boolean faulty,
                          String reason) {
    }

    record NoMatchJson(String event, double time, long line) {
    }

    record RestartedJson(String event, String reason) {
    }

    String toText(MonitorEvent e) {
        if (e instanceof MonitorEvent.Warning w) {
            warning = w;
            return String.format(Locale.ROOT, "t=%.3f line %d: WARNING: the run can only be faulty scenario %s "
                    + "(every nominal model eliminated); battery %s", w.time(), w.line(),
                    String.join(", ", w.scenarios()), battery(w.battery()));
        }
        if (e instanceof MonitorEvent.Violation v) {
            String lead = warning == null ? "no warning came before it"
                    : String.format(Locale.ROOT, "lead of the warning: %.3f s, battery %s at the warning vs %s now",
                    v.time() - warning.time(), battery(warning.battery()), battery(v.value()));
            return String.format(Locale.ROOT, "t=%.3f line %d: VIOLATION of '%s': %s; %s", v.time(), v.line(),
                    v.property(), battery(v.value()), lead);
        }
        if (e instanceof MonitorEvent.Eliminated x) {
            return verbose ? String.format(Locale.ROOT, "t=%.3f line %d: model %s (%s) eliminated: %s", x.time(),
                    x.line(), x.model(), x.faulty() ? "faulty" : "nominal", x.reason()) : null;
        }
        if (e instanceof MonitorEvent.NoMatch n) {
            return String.format(Locale.ROOT, "t=%.3f line %d: no learned scenario matches this run any more",
                    n.time(), n.line());
        }
        if (e instanceof MonitorEvent.Restarted r) {
            warning = null;
            return "log " + r.reason() + ": monitoring starts over";
        }
        return null;
    }

    private static String battery(Double b) {
        return b == null ? "unknown" : String.format(Locale.ROOT, "%.2f", b);
    }
}
