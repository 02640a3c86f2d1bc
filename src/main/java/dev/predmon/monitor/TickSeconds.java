package dev.predmon.monitor;

import dev.predmon.forecast.Forecast;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;

import java.math.BigDecimal;
import java.math.MathContext;

/**
 * How long a tick of the tree lasts, for logs without time stamps ({@code watch --tick-seconds S}): such a log is
 * counted in ticks, and with a length given every time the monitor reports (its events, its forecasts, the records
 * the live page plots) is in seconds instead. What the monitor learns from and where it cuts runs stay in ticks.
 *
 * @param seconds seconds per tick; NaN for none (times stay as the log counts them)
 */
public record TickSeconds(double seconds) {

    /** No length given: a log without time stamps is counted in ticks. */
    public static final TickSeconds NONE = new TickSeconds(Double.NaN);

    public TickSeconds {
        if (!Double.isNaN(seconds) && !(seconds > 0 && Double.isFinite(seconds))) {
            throw new IllegalArgumentException("a tick lasts a positive number of seconds, got " + seconds);
        }
    }

    private boolean on(Clock clock) {
        return clock == Clock.TICKS && !Double.isNaN(seconds);
    }

    /** What a log of {@code clock} is reported in. */
    public Clock clock(Clock clock) {
        return on(clock) ? Clock.SECONDS : clock;
    }

    /** {@code r} with its time in seconds, when it counts ticks. */
    public LogRecord record(LogRecord r) {
        return on(r.clock()) ? new LogRecord(r.line(), times(r.time()), r.level(), r.kind(), r.from(), r.to(),
                r.protocol(), r.command(), r.arguments(), r.reply(), Clock.SECONDS) : r;
    }

    /** {@code f} with its times in seconds and its drift per second, when it counts ticks. */
    public Forecast forecast(Forecast f) {
        if (f == null || Double.isNaN(seconds) || !Clock.TICKS.unit().equals(f.unit())) {
            return f;
        }
        Double perSecond = f.drift() == null ? null : BigDecimal.valueOf(f.drift())
                .divide(BigDecimal.valueOf(seconds), MathContext.DECIMAL64).doubleValue();
        return new Forecast(f.probability(), times(f.timeToViolation()), times(f.low()), times(f.high()), f.basis(),
                f.novelSince(), f.runs(), f.violated(), f.value(), perSecond, Clock.SECONDS.unit());
    }

    private Double times(Double ticks) {
        return ticks == null ? null : times(ticks.doubleValue());
    }

    /**
     * {@code ticks} in seconds, as the decimal product (0.1 s a tick makes tick 93 read 9.3, not 9.300000000000001).
     */
    private double times(double ticks) {
        return BigDecimal.valueOf(ticks).multiply(BigDecimal.valueOf(seconds)).doubleValue();
    }

    /** {@code e} with its time in seconds and its forecast too, when it counts ticks. */
    public MonitorEvent event(MonitorEvent e) {
        if (e instanceof MonitorEvent.Warning w && on(w.clock())) {
            return new MonitorEvent.Warning(times(w.time()), w.line(), w.scenarios(), w.value(), w.pairs(),
                    Clock.SECONDS, w.run(), w.rule(), forecast(w.forecast()), w.reason(), w.clause(), w.scenario(),
                    w.property(), w.deadline());
        }
        if (e instanceof MonitorEvent.Violation v && on(v.clock())) {
            return new MonitorEvent.Violation(times(v.time()), v.line(), v.property(), v.name(), v.value(), v.before(),
                    v.what(), Clock.SECONDS, v.run(), v.forecast());
        }
        if (e instanceof MonitorEvent.ForecastChanged f && on(f.clock())) {
            return new MonitorEvent.ForecastChanged(times(f.time()), f.line(), forecast(f.forecast()),
                    Clock.SECONDS, f.run(), f.property(), f.deadline(), f.unit());
        }
        if (e instanceof MonitorEvent.Eliminated x && on(x.clock())) {
            return new MonitorEvent.Eliminated(times(x.time()), x.line(), x.model(), x.scenario(), x.faulty(),
                    x.reason(), Clock.SECONDS, x.run());
        }
        if (e instanceof MonitorEvent.NoMatch n && on(n.clock())) {
            return new MonitorEvent.NoMatch(times(n.time()), n.line(), Clock.SECONDS, n.run());
        }
        if (e instanceof MonitorEvent.Recovered r && on(r.clock())) {
            return new MonitorEvent.Recovered(times(r.time()), r.line(), r.cause(), r.value(), r.reason(),
                    Clock.SECONDS, r.run(), r.property());
        }
        if (e instanceof MonitorEvent.UnderWay u && on(u.clock())) {
            return new MonitorEvent.UnderWay(times(u.time()), u.line(), u.by(), u.underWay(), Clock.SECONDS, u.run());
        }
        if (e instanceof MonitorEvent.RunStarted r && on(r.clock())) {
            return new MonitorEvent.RunStarted(r.run(), times(r.time()), r.line(), Clock.SECONDS);
        }
        return e;
    }
}
