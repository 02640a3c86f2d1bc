package dev.predmon.property;

import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Iterator;
import java.util.LinkedHashMap;

/**
 * The check of a {@link Response}: the obligations open, each since when and until when with the count of the
 * counted event, and whether the trigger's condition held at the last reading. Without {@link Response#per} one
 * obligation at most is open (constant state); with it, one per instance whose trigger is unanswered, each removed as
 * it ends, so the state is bounded by the triggers within one deadline.
 */
final class ResponseCheck extends Check {

    /** One open obligation: its trigger's line, since when, until when, its count, and its deadline's scale. */
    private static final class Obligation {
        long line;
        double since;
        double deadline;
        long count;
        /** Its deadline's seconds per unit of the log's clock (a tick's length for seconds in a log of ticks), else 1. */
        double scale = 1;
    }

    private final Response p;
    private final Deadline d;
    /** The open obligations by instance ({@code ""} for all without {@code per}), in the order they opened. */
    private final LinkedHashMap<String, Obligation> open = new LinkedHashMap<>();
    private boolean held;
    /** Whether a lasting response holds (only with {@code cancelledBy}). */
    private boolean answered;
    /** Whether the trigger's state (the condition held and no response lasted) held at the last reading. */
    private boolean owing;
    /** Where the run was at the last record, on the deadline's clock (the log's ticks for seconds of ticks). */
    private double now;
    /** Seconds per tick of a log without time stamps, NaN when not given ({@link #countTicksAs}). */
    private double tickSeconds = Double.NaN;
    /**
     * {@link #first()} as last found, for the obligations as they were after {@code edits} changes (an obligation
     * opened or closed, or a count moved) and at {@link #now} {@code firstNow}: the monitor asks for it several times
     * a record, and one obligation is all that is open most of the time.
     */
    private Obligation nearestFound;
    private long edits;
    private long firstEdits = -1;
    private double firstNow;

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

    /** The instance {@code r} acts on. */
    private String instance(LogRecord r) {
        return p.per() == null ? "" : p.per().of(r);
    }

    @Override
    Verdict.Violated step(LogRecord r, long ticks) {
        opened = -1;
        // Whether r is a response, asked at most once per record: null until asked.
        Boolean responds = null;
        if (!open.isEmpty()) {
            if (d.unit() == Deadline.Unit.OCCURRENCES && d.counted().matches(r)) {
                Obligation o = open.get(instance(r));
                if (o != null) {
                    o.count++;
                    edits++;
                }
            }
            now = now(r, ticks);
            Obligation late = removeOverdue();
            if (late != null) {
                obligations.closed(late.line, elapsed(late), false);
                return new Verdict.Violated(r.line(), r.time(), null, null, missed(late));
            }
            responds = p.response().matches(r);
            if (responds) {
                Obligation o = open.remove(instance(r));
                if (o != null) {
                    edits++;
                    obligations.closed(o.line, elapsed(o), true);
                }
            }
        }
        if (p.cancelledBy() != null) {
            boolean response = responds != null ? responds : p.response().matches(r);
            answered = response || (answered && !p.cancelledBy().matches(r));
        }
        if (fires(r)) {
            String key = instance(r);
            if (!open.containsKey(key)) {
                openAt(r, ticks, key);
            }
        }
        return null;
    }

    private void openAt(LogRecord r, long ticks, String key) {
        Obligation o = new Obligation();
        o.line = r.line();
        opened = r.line();
        o.count = d.unit() == Deadline.Unit.OCCURRENCES && d.counted().matches(r) ? 1 : 0;
        o.since = d.unit() == Deadline.Unit.OCCURRENCES ? o.count : now(r, ticks);
        if (open.isEmpty()) {
            now = o.since;
        }
        // T seconds in a log that counts ticks of a known length are T / length ticks, as a decimal quotient
        o.scale = d.unit() == Deadline.Unit.SECONDS && r.clock() == Clock.TICKS && !Double.isNaN(tickSeconds)
                ? tickSeconds : 1;
        o.deadline = d.unit() == Deadline.Unit.OCCURRENCES ? d.amount() : o.since + (o.scale == 1 ? d.amount()
                : BigDecimal.valueOf(d.amount()).divide(BigDecimal.valueOf(o.scale), MathContext.DECIMAL64)
                .doubleValue());
        open.put(key, o);
        edits++;
    }

    /** A tick of a log without time stamps lasts {@code seconds} (NaN: unknown, a tick counts as a second). */
    @Override
    void countTicksAs(double seconds) {
        tickSeconds = seconds;
    }

    /** Where {@code o} is on its deadline's clock: its count, or the run's clock. */
    private double at(Obligation o) {
        return d.unit() == Deadline.Unit.OCCURRENCES ? o.count : now;
    }

    /** How long {@code o} has been pending, in its deadline's unit: occurrences count from none. */
    private double elapsed(Obligation o) {
        return scaled(o, at(o) - (d.unit() == Deadline.Unit.OCCURRENCES ? 0 : o.since));
    }

    /**
     * Removes and gives the first open obligation whose deadline has passed at {@link #now}, or null: a single open
     * one is {@link #first()}, found once while it is open, without an iterator per record.
     */
    private Obligation removeOverdue() {
        Obligation late = null;
        if (open.size() == 1) {
            Obligation o = first();
            if (at(o) > o.deadline) {
                open.clear();
                late = o;
            }
        } else {
            for (Iterator<Obligation> it = open.values().iterator(); it.hasNext() && late == null; ) {
                Obligation o = it.next();
                if (at(o) > o.deadline) {
                    it.remove();
                    late = o;
                }
            }
        }
        if (late != null) {
            edits++;
        }
        return late;
    }

    /** The open obligation nearest its deadline (the earliest opened among equals), or null. */
    private Obligation first() {
        if (firstEdits == edits && (open.size() <= 1 || Double.compare(firstNow, now) == 0)) {
            return nearestFound; // nothing it depends on changed: one obligation (or none) whatever the time, else the same time
        }
        Obligation nearest = null;
        for (Obligation o : open.values()) {
            if (nearest == null || o.deadline - at(o) < nearest.deadline - at(nearest)) {
                nearest = o;
            }
        }
        nearestFound = nearest;
        firstEdits = edits;
        firstNow = now;
        return nearest;
    }

    /**
     * A deadline in seconds passes while the log is silent: a robot that freezes logs nothing, and the silence may
     * begin a new run. {@code r}, the first record after it, is past the deadline: the obligation is violated there,
     * never dropped with its run. Ticks and occurrences do not pass while nothing is logged.
     */
    @Override
    Verdict.Violated overdue(LogRecord r) {
        Obligation o = first();
        if (o == null || d.unit() != Deadline.Unit.SECONDS || r.clock() == Clock.TICKS || !(r.time() > o.deadline)) {
            return null;
        }
        open.remove(key(o));
        edits++;
        double last = now;
        now = r.time();
        obligations.closed(o.line, now - o.since, false);
        return new Verdict.Violated(r.line(), r.time(), null, null, missed(o) + " (nothing was logged from t="
                + Numbers.text(last) + " until this record, past the deadline)");
    }

    private String key(Obligation o) {
        for (var e : open.entrySet()) {
            if (e.getValue() == o) {
                return e.getKey();
            }
        }
        return null;
    }

    @Override
    double elapsed() {
        Obligation o = first();
        return o == null ? Double.NaN : elapsed(o);
    }

    @Override
    long pendingLine() {
        Obligation o = first();
        return o == null ? -1 : o.line;
    }

    @Override
    void finish() {
        for (Obligation o : open.values()) {
            obligations.closed(o.line, elapsed(o), false);
        }
    }

    /** Where the run is, in the deadline's unit (occurrences are counted per obligation). */
    private double now(LogRecord r, long ticks) {
        return switch (d.unit()) {
            case TICKS -> ticks;
            case SECONDS -> r.time();
            case OCCURRENCES -> 0;
        };
    }

    /**
     * Whether {@code r} is a trigger: the event while no response lasts, or the record from which the condition holds
     * while no response lasts (a reading that makes it true, or a cancelling record while it holds).
     */
    private boolean fires(LogRecord r) {
        if (p.trigger() != null) {
            boolean event = p.trigger().matches(r);
            triggered = event ? 1 : 0;
            return event && !answered;
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
        Obligation first = first();
        if (first == null) {
            return null;
        }
        for (Obligation o : open.values()) {
            obligations.closed(o.line, elapsed(o), false);
        }
        open.clear();
        edits++;
        return new Verdict.Violated(r.line(), r.time(), null, null, "the scope ended before "
                + p.response().brief() + " answered " + p.briefTrigger() + " at line " + first.line);
    }

    /**
     * The missed deadline in an operator's words: {@code 8 closeHand attempts since line 6650, none answered by
     * hasGrasped 1 or 27503}; {@code no getStatus 2 or halt in 400 ticks since goTo at line 24}.
     */
    private String missed(Obligation o) {
        String amount = Numbers.text(d.amount());
        return switch (d.unit()) {
            case OCCURRENCES -> amount + " " + d.counted().brief() + (d.amount() == 1 ? " attempt" : " attempts")
                    + " since line " + o.line + ", none answered by " + p.response().brief();
            case TICKS, SECONDS -> "no " + p.response().brief() + " in " + amount + " "
                    + (d.unit() == Deadline.Unit.TICKS ? "ticks" : "s") + " since " + p.briefTrigger() + " at line "
                    + o.line;
        };
    }

    @Override
    Verdict owed() {
        Obligation o = first();
        if (o == null) {
            return Verdict.HOLDS;
        }
        return new Verdict.Pending(o.line, scaled(o, o.since), scaled(o, o.deadline), d.unit());
    }

    /** {@code v}, on the log's clock, in {@code o}'s deadline's unit. */
    private static double scaled(Obligation o, double v) {
        return o.scale == 1 ? v : BigDecimal.valueOf(v).multiply(BigDecimal.valueOf(o.scale)).doubleValue();
    }

    @Override
    void reset() {
        open.clear();
        edits++;
        held = false;
        answered = false;
        owing = false;
    }
}
