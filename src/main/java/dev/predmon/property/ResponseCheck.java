package dev.predmon.property;

import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;

import java.math.BigDecimal;
import java.math.MathContext;

/**
 * The check of a {@link Response}: whether an obligation is open, since when and until when, the count of the
 * counted event, and whether the trigger's condition held at the last reading. Constant state.
 */
final class ResponseCheck extends Check {

    private final Response p;
    private final Deadline d;
    private boolean pending;
    private long line;
    private double since;
    private double deadline;
    private long count;
    private boolean held;
    /** Whether a lasting response holds (only with {@code cancelledBy}). */
    private boolean answered;
    /** Whether the trigger's state (the condition held and no response lasted) held at the last reading. */
    private boolean owing;
    /** Where the run was at the last record, on the deadline's clock (the log's ticks for seconds of ticks). */
    private double now;
    /**
     * Seconds per tick of a log without time stamps, NaN when not given ({@link #countTicksAs}); and the open
     * obligation's: its deadline's seconds per unit of the log's clock (a tick's length for a deadline in seconds in
     * such a log, else 1). The check runs on the log's clock; what it reports is in the deadline's unit.
     */
    private double tickSeconds = Double.NaN;
    private double scale = 1;

    private final Readings readings;
    /** The condition's value's slot in {@link #readings}, or -1 for a trigger that is an event. */
    private final int slot;

    /** The trigger's messages, whatever their values, or null for a trigger that is a condition. */
    private final Event triggers;

    ResponseCheck(Response p, Readings readings) {
        this.p = p;
        this.d = p.within();
        this.readings = readings;
        this.slot = p.condition() == null ? -1 : readings.slot(p.condition().value());
        this.triggers = p.trigger() == null ? null : p.trigger().messages();
    }

    @Override
    boolean evidences(LogRecord r) {
        return triggers != null ? triggers.matches(r) : !Double.isNaN(readings.value(slot));
    }

    @Override
    String unseen() {
        return triggers != null ? "no " + triggers.describe() + " (its trigger)"
                : "no reading of " + p.condition().value().describeWithPorts() + " (its trigger's value)";
    }

    @Override
    Verdict.Violated step(LogRecord r, long ticks) {
        // Whether r is a response, asked at most once per record: null until asked.
        Boolean responds = null;
        if (pending) {
            if (d.unit() == Deadline.Unit.OCCURRENCES && d.counted().matches(r)) {
                count++;
            }
            now = now(r, ticks);
            if (now > deadline) {
                pending = false;
                obligations.closed(inUnit(now - since()), false);
                return new Verdict.Violated(r.line(), r.time(), null, null, missed());
            }
            responds = p.response().matches(r);
            if (responds) {
                pending = false;
                obligations.closed(inUnit(now - since()), true);
            }
        }
        if (p.cancelledBy() != null) {
            boolean response = responds != null ? responds : p.response().matches(r);
            answered = response || (answered && !p.cancelledBy().matches(r));
        }
        if (fires(r) && !pending) {
            pending = true;
            line = r.line();
            count = d.unit() == Deadline.Unit.OCCURRENCES && d.counted().matches(r) ? 1 : 0;
            since = now(r, ticks);
            now = since;
            // T seconds in a log that counts ticks of a known length are T / length ticks, as a decimal quotient
            scale = d.unit() == Deadline.Unit.SECONDS && r.clock() == Clock.TICKS && !Double.isNaN(tickSeconds)
                    ? tickSeconds : 1;
            deadline = d.unit() == Deadline.Unit.OCCURRENCES ? d.amount() : since + (scale == 1 ? d.amount()
                    : BigDecimal.valueOf(d.amount()).divide(BigDecimal.valueOf(scale), MathContext.DECIMAL64)
                    .doubleValue());
        }
        return null;
    }

    /** A tick of a log without time stamps lasts {@code seconds} (NaN: unknown, a tick counts as a second). */
    @Override
    void countTicksAs(double seconds) {
        tickSeconds = seconds;
    }

    /** {@code v}, on the log's clock, in the open obligation's deadline's unit. */
    private double inUnit(double v) {
        return scale == 1 ? v : BigDecimal.valueOf(v).multiply(BigDecimal.valueOf(scale)).doubleValue();
    }

    /**
     * A deadline in seconds passes while the log is silent: a robot that freezes logs nothing, and the silence may
     * begin a new run. {@code r}, the first record after it, is past the deadline: the obligation is violated there,
     * never dropped with its run. Ticks and occurrences do not pass while nothing is logged.
     */
    @Override
    Verdict.Violated overdue(LogRecord r) {
        if (!pending || d.unit() != Deadline.Unit.SECONDS || r.clock() == Clock.TICKS || !(r.time() > deadline)) {
            return null;
        }
        pending = false;
        double last = now;
        now = r.time();
        obligations.closed(now - since, false);
        return new Verdict.Violated(r.line(), r.time(), null, null, missed() + " (nothing was logged from t="
                + Numbers.text(last) + " until this record, past the deadline)");
    }

    /** Where the obligation began, in the deadline's unit: occurrences count from none. */
    private double since() {
        return d.unit() == Deadline.Unit.OCCURRENCES ? 0 : since;
    }

    @Override
    double elapsed() {
        return pending ? inUnit(now - since()) : Double.NaN;
    }

    @Override
    void finish() {
        if (pending) {
            obligations.closed(inUnit(now - since()), false);
        }
    }

    /** Where the run is, in the deadline's unit. */
    private double now(LogRecord r, long ticks) {
        return switch (d.unit()) {
            case TICKS -> ticks;
            case SECONDS -> r.time();
            case OCCURRENCES -> count;
        };
    }

    /**
     * Whether {@code r} is a trigger: the event while no response lasts, or the record from which the condition holds
     * while no response lasts (a reading that makes it true, or a cancelling record while it holds).
     */
    private boolean fires(LogRecord r) {
        if (p.trigger() != null) {
            return p.trigger().matches(r) && !answered;
        }
        double v = readings.value(slot); // p.condition().value().valueOf(r), read once for every property
        if (!Double.isNaN(v)) {
            held = p.condition().test(v);
        }
        boolean was = owing;
        owing = held && !answered;
        return owing && !was;
    }

    @Override
    Verdict.Violated close(LogRecord r) {
        if (!pending) {
            return null;
        }
        pending = false;
        obligations.closed(inUnit(now - since()), false);
        return new Verdict.Violated(r.line(), r.time(), null, null, "the scope ended before "
                + p.response().brief() + " answered " + p.briefTrigger() + " at line " + line);
    }

    /**
     * The missed deadline in an operator's words: {@code 8 closeHand attempts since line 6650, none answered by
     * hasGrasped 1 or 27503}; {@code no getStatus 2 or halt in 400 ticks since goTo at line 24}.
     */
    private String missed() {
        String amount = Numbers.text(d.amount());
        return switch (d.unit()) {
            case OCCURRENCES -> amount + " " + d.counted().brief() + (d.amount() == 1 ? " attempt" : " attempts")
                    + " since line " + line + ", none answered by " + p.response().brief();
            case TICKS, SECONDS -> "no " + p.response().brief() + " in " + amount + " "
                    + (d.unit() == Deadline.Unit.TICKS ? "ticks" : "s") + " since " + p.briefTrigger() + " at line "
                    + line;
        };
    }

    @Override
    Verdict owed() {
        return pending ? new Verdict.Pending(line, inUnit(since), inUnit(deadline), d.unit()) : Verdict.HOLDS;
    }

    @Override
    void reset() {
        pending = false;
        count = 0;
        held = false;
        answered = false;
        owing = false;
    }
}
