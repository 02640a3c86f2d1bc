package dev.predmon.cli;

import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.forecast.Survival;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.parse.Clock;

import java.io.PrintWriter;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * Prints monitor events as they happen: one readable line each, or with {@code --json} one JSON object per
 * line ({@code {"event":"warning","time":...,"scenario":...,"battery":...,"wallTime":...}}), flushed at once so a
 * pipe sees each warning immediately.
 */
final class EventPrinter implements Consumer<MonitorEvent> {

    private final PrintWriter out;
    private final boolean json;
    private final boolean verbose;
    private final String log;
    private final boolean timestamps;
    private MonitorEvent.Warning warning;

    /** @param eliminations also print each model's elimination (JSON always does) */
    EventPrinter(PrintWriter out, boolean json, boolean eliminations) {
        this(out, json, eliminations, null, false);
    }

    /**
     * For one log of several: each event says which ({@code "log"} in JSON, a {@code log: } prefix in text).
     *
     * @param log        the log's name, or null when only one log is watched
     * @param timestamps start each text line with the wall-clock time
     */
    EventPrinter(PrintWriter out, boolean json, boolean eliminations, String log, boolean timestamps) {
        this.out = out;
        this.json = json;
        this.verbose = eliminations;
        this.log = log;
        this.timestamps = timestamps;
    }

    @Override
    public void accept(MonitorEvent e) {
        accept(e, Instant.now());
    }

    /** Prints {@code e}, which happened at wall-clock time {@code at}. */
    void accept(MonitorEvent e, Instant at) {
        if (e instanceof MonitorEvent.Unmapped) {
            return; // the caller reports these with the parse problems
        }
        if (json) {
            out.println(toJson(e, log, at));
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
            out.println(Json.line(Json.stamped(o, log, at)));
        } else {
            out.println(Terminal.line(line("heartbeat: " + (!present && records == 0 ? "waiting for the file"
                    : "line " + line + ", run " + run + ", " + records + " records; " + (forecast == null
                    ? "no forecast yet" : "forecast: " + ForecastWords.line(forecast))), at)));
        }
        out.flush();
    }

    /** A text line as printed: the wall-clock time with {@code --timestamps}, then the log's name in a fleet. */
    String line(String text, Instant at) {
        return (timestamps ? Json.wallTime(at) + " " : "") + (log == null ? text : log + ": " + text);
    }

    /** The JSON object of an event ({@link MonitorEvent.Unmapped} is not one: it goes to stderr with the problems). */
    static String toJson(MonitorEvent e) {
        return toJson(e, null);
    }

    /** The JSON object of an event of {@code log} ({@code "log"} right after {@code "event"}), or untagged if null. */
    static String toJson(MonitorEvent e, String log) {
        return toJson(e, log, Instant.now());
    }

    /**
     * The JSON object of an event of {@code log} ({@code "log"} right after {@code "event"}, or untagged if null),
     * written at wall-clock time {@code at} ({@code "wallTime"}, last).
     */
    static String toJson(MonitorEvent e, String log, Instant at) {
        Object o;
        if (e instanceof MonitorEvent.Warning w) {
            o = new WarningJson("warning", w.time(), w.clock().unit(), w.line(), w.run(), w.property(), w.scenario(),
                    w.scenarios(), w.battery(), w.pairs(), w.rule().id(), w.clause().id(), w.reason(),
                    ForecastJson.of(w.forecast()), DeadlineJson.of(w.deadline()));
        } else if (e instanceof MonitorEvent.ForecastChanged f) {
            o = new ForecastEventJson("forecast", f.time(), f.clock().unit(), f.line(), f.run(),
                    ForecastJson.of(f.forecast()), f.property(), DeadlineJson.of(f.deadline()));
        } else if (e instanceof MonitorEvent.Violation v) {
            o = new ViolationJson("violation", v.time(), v.clock().unit(), v.line(), v.run(), v.property(), v.name(),
                    v.value(), v.forecast() ? v.value() : null, v.before(), v.what());
        } else if (e instanceof MonitorEvent.Eliminated x) {
            o = new EliminatedJson("eliminated", x.time(), x.clock().unit(), x.line(), x.run(), x.model(), x.scenario(),
                    x.faulty(), x.reason());
        } else if (e instanceof MonitorEvent.NoMatch n) {
            o = new NoMatchJson("no-match", n.time(), n.clock().unit(), n.line(), n.run());
        } else if (e instanceof MonitorEvent.RunStarted r) {
            o = new RunJson("run", r.run(), r.time(), r.clock().unit(), r.line());
        } else if (e instanceof MonitorEvent.Restarted r) {
            o = new RestartedJson("restarted", r.reason());
        } else if (e instanceof MonitorEvent.Recovered r) {
            o = new RecoveredJson("recovered", r.time(), r.clock().unit(), r.line(), r.run(), r.cause(),
                    Double.isNaN(r.value()) ? null : r.value(), r.reason(), r.property());
        } else if (e instanceof MonitorEvent.UnderWay u) {
            o = new UnderWayJson("under-way", u.time(), u.clock().unit(), u.line(), u.run(), u.by(), u.underWay());
        } else {
            throw new IllegalArgumentException("not printed as a JSON event: " + e);
        }
        return Json.line(Json.stamped(o, log, at));
    }

    record HeartbeatJson(String event, boolean present, long line, int run, long records, ForecastJson forecast) {
    }

    record WarningJson(String event, double time, String unit, long line, int run, String property,
                       String scenario, List<String> scenarios, Double battery, long pairs, String rule, String clause,
                       String reason, ForecastJson forecast, DeadlineJson deadline) {
    }

    /**
     * A deadline forecast: {@code probability} of a miss (null when the obligation is past every training one:
     * {@code novel}), {@code timeLeft} before the deadline in its unit, {@code atRisk} training obligations pending
     * as long, {@code longer} of them still pending at the deadline.
     */
    record DeadlineJson(Double probability, double timeLeft, int atRisk, int longer, boolean novel) {
        static DeadlineJson of(Survival.Estimate e) {
            return e == null ? null : new DeadlineJson(e.novel() ? null : e.probability(), e.timeLeft(), e.atRisk(),
                    e.longer(), e.novel());
        }
    }

    /** A recovery: {@code battery} the property's value (null for a property without one), {@code property} its id. */
    record RecoveredJson(String event, double time, String unit, long line, int run, String cause, Double battery,
                         String reason, String property) {
    }

    record UnderWayJson(String event, double time, String unit, long line, int run, String by, boolean underWay) {
    }

    /** A forecast: the forecast property's ({@code forecast}), or a bounded response's deadline ({@code deadline}). */
    record ForecastEventJson(String event, double time, String unit, long line, int run, ForecastJson forecast,
                             String property, DeadlineJson deadline) {
    }

    /**
     * A property's violation: {@code property} its id, {@code name} its words, {@code value} the violating value of a
     * bound (null for an event), {@code battery} the same for the forecast's property only, {@code what} in words.
     */
    record ViolationJson(String event, double time, String unit, long line, int run, String property, String name,
                         Double value, Double battery, Double before, String what) {
    }

    record EliminatedJson(String event, double time, String unit, long line, int run, String model, String scenario,
                          boolean faulty, String reason) {
    }

    record NoMatchJson(String event, double time, String unit, long line, int run) {
    }

    record RunJson(String event, int run, double time, String unit, long line) {
    }

    record RestartedJson(String event, String reason) {
    }

    String toText(MonitorEvent e) {
        if (e instanceof MonitorEvent.Warning w && w.deadline() != null) {
            return String.format(Locale.ROOT, "%s line %d: WARNING: %s", at(w.time(), w.clock()), w.line(),
                    w.reason());
        }
        if (e instanceof MonitorEvent.Warning w) {
            warning = w;
            return String.format(Locale.ROOT, "%s line %d: WARNING: %s; battery %s", at(w.time(), w.clock()), w.line(),
                    w.reason(), battery(w.battery()));
        }
        if (e instanceof MonitorEvent.ForecastChanged f && f.deadline() != null) {
            return verbose ? String.format(Locale.ROOT, "%s line %d: forecast of %s: %s", at(f.time(), f.clock()),
                    f.line(), f.property(), f.deadline().novel() ? "pending longer than any training obligation, "
                    + ForecastWords.fixed(f.deadline().timeLeft(), 0) + " left" : "P(miss) "
                    + ForecastWords.fixed(f.deadline().probability(), 2) + ", "
                    + ForecastWords.fixed(f.deadline().timeLeft(), 0) + " left") : null;
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
                    : String.format(Locale.ROOT, "lead of the warning: %s, battery %s at the warning vs %s now",
                    span(v.time() - warning.time(), v.clock()), battery(warning.battery()), battery(v.value()));
            return String.format(Locale.ROOT, "%s line %d: VIOLATION of '%s': %s; %s", at(v.time(), v.clock()), v.line(),
                    v.name(), battery(v.value()), lead);
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
            return String.format(Locale.ROOT, "%s line %d: RECOVERED: %s", at(r.time(), r.clock()), r.line(),
                    r.reason());
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
