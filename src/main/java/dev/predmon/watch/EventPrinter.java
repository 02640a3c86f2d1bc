package dev.predmon.watch;

import dev.predmon.Terminal;
import dev.predmon.event.EventJson;
import dev.predmon.event.ForecastJson;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.parse.Clock;

import java.io.PrintWriter;
import java.time.Instant;
import java.util.Locale;

/**
 * Prints one log's monitor events on stdout as they happen: one readable line each, or with {@code --json} one JSON
 * object per line ({@link EventJson}: {@code {"event":"warning","time":...,"scenario":...,"wallTime":...}}), flushed
 * at once so a pipe sees each warning immediately.
 */
final class EventPrinter {

    private final PrintWriter out;
    private final boolean json;
    private final boolean verbose;
    private final String log;
    private final Stamp stamp;
    private MonitorEvent.Warning warning;
    /** The id of the property the monitor's own forecast is about; another's warnings name their property. */
    private String forecastId;

    /**
     * For one log of several, each event says which ({@code "log"} in JSON, a {@code log: } prefix in text).
     *
     * @param eliminations also print each model's elimination (JSON always does)
     * @param log          the log's name, or null when only one log is watched
     * @param stamp        what begins each text line
     */
    EventPrinter(PrintWriter out, boolean json, boolean eliminations, String log, Stamp stamp) {
        this.out = out;
        this.json = json;
        this.verbose = eliminations;
        this.log = log;
        this.stamp = stamp;
    }

    /**
     * The id of the property the monitor's own forecast is about (null without one): the lead of its violation is
     * from its warning, and another bound property's warnings and forecasts name their property.
     */
    EventPrinter forecastProperty(String id) {
        this.forecastId = id;
        return this;
    }

    /** Prints {@code e}, which happened at wall-clock time {@code at}. */
    void accept(MonitorEvent e, Instant at) {
        if (e instanceof MonitorEvent.Unmapped) {
            return; // the caller reports these with the parse problems
        }
        if (json) {
            out.println(EventJson.line(EventJson.of(e, log, at)));
        } else {
            String text = toText(e);
            if (text != null) {
                out.println(Terminal.line(line(text, at)));
            }
        }
        out.flush();
    }

    /**
     * Every {@code --heartbeat}: the log's line, run and latest forecast, as a text line or a {@code heartbeat} event.
     *
     * @param line     lines of the file being read
     * @param forecast the run's latest forecast, or null before any
     * @param present  whether the file exists
     */
    void heartbeat(long line, int run, long records, Forecast forecast, boolean present, Instant at) {
        if (json) {
            HeartbeatJson o = new HeartbeatJson("heartbeat", present, line, run, records, ForecastJson.of(forecast));
            out.println(EventJson.line(EventJson.stamped(o, log, at)));
        } else {
            out.println(Terminal.line(line("heartbeat: " + (!present && records == 0 ? "waiting for the file"
                    : "line " + line + ", run " + run + ", " + records + " records; " + (forecast == null
                    ? "no forecast yet" : "forecast: " + ForecastWords.line(forecast))), at)));
        }
        out.flush();
    }

    /** A text line as printed: the stamp ({@link Stamp}), then the log's name in a fleet. */
    String line(String text, Instant at) {
        return stamp.of(at) + (log == null ? text : log + ": " + text);
    }

    record HeartbeatJson(String event, boolean present, long line, int run, long records, ForecastJson forecast) {
    }

    /** Whether {@code property} is another than the one the monitor's own forecast is about. */
    private boolean other(String property) {
        return property != null && forecastId != null && !property.equals(forecastId);
    }

    /** {@code e} as a text line (without the stamp), or null when it is not printed as text. */
    String toText(MonitorEvent e) {
        if (e instanceof MonitorEvent.Warning w && (w.deadline() != null || other(w.property()))) {
            return String.format(Locale.ROOT, "%s line %d: WARNING: %s", at(w.time(), w.clock()), w.line(),
                    w.reason());
        }
        if (e instanceof MonitorEvent.Warning w) {
            warning = w;
            return String.format(Locale.ROOT, "%s line %d: WARNING: %s; %s %s", at(w.time(), w.clock()), w.line(),
                    w.reason(), named(w.property()), value(w.value()));
        }
        if (e instanceof MonitorEvent.ForecastChanged f && f.deadline() != null) {
            return verbose ? String.format(Locale.ROOT, "%s line %d: forecast of %s: %s", at(f.time(), f.clock()),
                    f.line(), f.property(), (f.deadline().novel() ? "pending longer than any training obligation, "
                    : "P(miss) " + ForecastWords.fixed(f.deadline().probability(), 2) + ", ")
                    + ForecastWords.fixed(f.deadline().timeLeft(), 0) + (f.unit() == null ? "" : " " + f.unit())
                    + " left") : null;
        }
        if (e instanceof MonitorEvent.ForecastChanged f && other(f.property())) {
            return verbose ? String.format(Locale.ROOT, "%s line %d: forecast of %s: %s", at(f.time(), f.clock()),
                    f.line(), f.property(), ForecastWords.line(f.forecast())) : null;
        }
        if (e instanceof MonitorEvent.ForecastChanged f) {
            return verbose ? String.format(Locale.ROOT, "%s line %d: forecast: %s", at(f.time(), f.clock()), f.line(),
                    ForecastWords.line(f.forecast())) : null;
        }
        if (e instanceof MonitorEvent.Violation v && !v.forecast()) {
            return String.format(Locale.ROOT, "%s line %d: VIOLATION of '%s' (%s): %s", at(v.time(), v.clock()),
                    v.line(), v.name(), v.property(), v.what());
        }
        if (e instanceof MonitorEvent.Violation v) {
            String lead = warning == null ? "no warning came before it"
                    : String.format(Locale.ROOT, "lead of the warning: %s, %s %s at the warning vs %s now",
                    span(v.time() - warning.time(), v.clock()), named(v.property()), value(warning.value()),
                    value(v.value()));
            return String.format(Locale.ROOT, "%s line %d: VIOLATION of '%s': %s; %s", at(v.time(), v.clock()), v.line(),
                    v.name(), value(v.value()), lead);
        }
        if (e instanceof MonitorEvent.Eliminated x) {
            return verbose ? String.format(Locale.ROOT, "%s line %d: model %s (%s) eliminated: %s", at(x.time(), x.clock()),
                    x.line(), x.model(), x.faulty() ? "faulty" : "nominal", x.reason()) : null;
        }
        if (e instanceof MonitorEvent.NoMatch n) {
            return String.format(Locale.ROOT, "%s line %d: no learned scenario matches this run any more",
                    at(n.time(), n.clock()), n.line());
        }
        if (e instanceof MonitorEvent.Recovered r) {
            // an alarm its run took with it: nothing recovered, the run is over
            return String.format(Locale.ROOT, "%s line %d: %s: %s", at(r.time(), r.clock()), r.line(),
                    r.cause().equals(MonitorEvent.Recovered.RUN_ENDED) ? "ALARM ENDS WITH ITS RUN" : "RECOVERED", r.reason());
        }
        if (e instanceof MonitorEvent.UnderWay u) {
            return verbose ? String.format(Locale.ROOT, "%s line %d: the recommended action is %s (%s)",
                    at(u.time(), u.clock()), u.line(), u.underWay() ? "under way" : "no longer under way", u.by())
                    : null;
        }
        if (e instanceof MonitorEvent.RunStarted r) {
            warning = null;
            return String.format(Locale.ROOT, "%s line %d: run %d begins: every model starts over",
                    at(r.time(), r.clock()), r.line(), r.run());
        }
        if (e instanceof MonitorEvent.Restarted r) {
            warning = null;
            return r.words() + ": monitoring starts over";
        }
        return null;
    }

    /** When an event happened: {@code t=71.819} in seconds, {@code tick 188} in a log without time stamps. */
    static String at(double time, Clock clock) {
        return clock == Clock.TICKS ? String.format(Locale.ROOT, "tick %.0f", time)
                : String.format(Locale.ROOT, "t=%.3f", time);
    }

    /** A duration with its unit: {@code 5.026 s} or {@code 48 ticks}. */
    public static String span(double amount, Clock clock) {
        return clock == Clock.TICKS ? String.format(Locale.ROOT, "%.0f ticks", amount)
                : String.format(Locale.ROOT, "%.3f s", amount);
    }

    /** What a value is of: the property's id ({@code battery 27.83}), or {@code value} when it has none. */
    private static String named(String property) {
        return property == null ? "value" : property;
    }

    private static String value(Double v) {
        return v == null ? "unknown" : String.format(Locale.ROOT, "%.2f", v);
    }
}
