package dev.predmon.property;

import dev.predmon.parse.LogRecord;

/**
 * The incremental check of one property within one segment of its scope: constant state, one step per record.
 * {@link PropertyChecker} keeps the first violation and the scope; a check only says what each record does.
 */
abstract class Check {

    /** The value this record gave a {@link Bound}, NaN for any other record or kind. */
    double reading = Double.NaN;
    /**
     * Whether the checker will keep nothing of a violation this record makes but that it made one (the property is
     * violated already, and its first violation is its verdict): a bound then answers {@link #AGAIN} instead of
     * putting the reading in words at every reading of a long violation. Set by the checker.
     */
    boolean wordless;

    /** A violation the checker keeps nothing of but that it happened ({@link #wordless}). */
    static final Verdict.Violated AGAIN = new Verdict.Violated(0, Double.NaN, null, null, "violated again");

    /**
     * The next record of the segment.
     *
     * @param ticks {@code Tick} records of the run so far, this one included
     * @return the violation this record makes, or null
     */
    abstract Verdict.Violated step(LogRecord r, long ticks);

    /** The segment ends at {@code r} (after its step): a violation if something is still owed, else null. */
    Verdict.Violated close(LogRecord r) {
        return null;
    }

    /** What is owed now, if anything: {@link Verdict.Pending}, else {@link Verdict#HOLDS}. */
    Verdict owed() {
        return Verdict.HOLDS;
    }

    /**
     * Told how each obligation of a bounded response ended: what learning measures the deadline forecast on
     * ({@code forecast.Survival}).
     */
    @FunctionalInterface
    interface Obligations {
        /**
         * An obligation ended.
         *
         * @param line       the line of the trigger that opened it
         * @param duration   how long it was pending, in its deadline's unit
         * @param discharged true when its response came; false when it was let go still pending (the deadline
         *                   passed, its scope closed, or the run ended): a censored duration
         */
        void closed(long line, double duration, boolean discharged);
    }

    /** Told how each obligation of a bounded response ended; set by the checker. */
    Obligations obligations = (line, duration, discharged) -> { };

    /** The line of the trigger whose obligation the last record opened, -1 when it opened none; set by the check. */
    long opened = -1;
    /**
     * Whether the last record was the property's trigger event, as the check asked it: 1 or 0, -1 when the check did not
     * ask (no trigger event, or the record ended its step before); set by the check.
     */
    int triggered = -1;

    /**
     * How long the open obligation has been pending, in its deadline's unit (ticks, seconds, or occurrences of the
     * counted event); NaN when none is open or the kind has none.
     */
    double elapsed() {
        return Double.NaN;
    }

    /**
     * The line of the trigger of the open obligation nearest its deadline (the one {@link #elapsed} tells), -1 when
     * none is open.
     */
    long pendingLine() {
        return -1;
    }

    /** The run ends: an obligation still open is told as censored at its elapsed time. */
    void finish() {
    }

    /**
     * Whether {@code r}, just stepped, is evidence for the property: a record of what it speaks of (a bound's value, an
     * absence's or a precedence's message, a response's trigger), whatever its argument or reply. Asked until the
     * first such record of the run.
     */
    abstract boolean evidences(LogRecord r);

    /** What no record of a run without evidence showed, in words: {@code no reading of BatteryReader/level}. */
    abstract String unseen();

    /**
     * The run ends and {@code r}, the first record after it, begins the next: the violation of an obligation whose
     * deadline passed before {@code r} came, or null.
     */
    Verdict.Violated overdue(LogRecord r) {
        return null;
    }

    /** A tick of a log without time stamps lasts {@code seconds} (NaN: unknown). */
    void countTicksAs(double seconds) {
    }

    /** Whether the check reads a value (a bound's, which the forecast follows even after the violation). */
    boolean reads() {
        return false;
    }

    /** Starts a segment afresh. */
    abstract void reset();

    /** The check of {@code p}, which takes the values it reads from {@code readings}. */
    static Check of(Property p, Readings readings) {
        if (p instanceof Bound b) {
            return new BoundCheck(b, readings);
        }
        if (p instanceof Absence a) {
            return new AbsenceCheck(a);
        }
        if (p instanceof Precedence q) {
            return new PrecedenceCheck(q);
        }
        if (p instanceof Response r) {
            return new ResponseCheck(r, readings);
        }
        throw new IllegalArgumentException("no check for a property of kind '" + p.kind() + "'"); // a new kind's
    }

    private static final class BoundCheck extends Check {
        private final Bound p;
        private final Readings readings;
        private final int slot;
        private double last = Double.NaN;

        BoundCheck(Bound p, Readings readings) {
            this.p = p;
            this.readings = readings;
            this.slot = readings.slot(p.value());
        }

        @Override
        Verdict.Violated step(LogRecord r, long ticks) {
            double v = readings.value(slot); // p.valueOf(r), read once for every property
            reading = v;
            if (Double.isNaN(v)) {
                return null;
            }
            double before = last;
            last = v;
            if (!p.violatedBy(v)) {
                return null;
            }
            if (wordless) {
                return AGAIN;
            }
            return new Verdict.Violated(r.line(), r.time(), v, Double.isNaN(before) ? null : before, p.violation(v));
        }

        @Override
        boolean reads() {
            return true;
        }

        @Override
        boolean evidences(LogRecord r) {
            return !Double.isNaN(reading);
        }

        @Override
        String unseen() {
            return "no reading of " + p.value().describeWithPorts();
        }

        @Override
        void reset() {
            last = Double.NaN;
        }
    }

    /** A check whose evidence is a message of its event's kind ({@link Event#evidence}): absence and precedence. */
    private abstract static class EventCheck extends Check {
        /** That one came is evidence that the event could have. */
        private final Event messages;

        EventCheck(Event event) {
            this.messages = event.evidence();
        }

        @Override
        final boolean evidences(LogRecord r) {
            return messages.matches(r);
        }

        @Override
        final String unseen() {
            return "no " + messages.describe();
        }
    }

    private static final class AbsenceCheck extends EventCheck {
        private final Absence p;

        AbsenceCheck(Absence p) {
            super(p.event());
            this.p = p;
        }

        @Override
        Verdict.Violated step(LogRecord r, long ticks) {
            return p.event().matches(r) ? new Verdict.Violated(r.line(), r.time(), null, null, p.event().describe())
                    : null;
        }

        @Override
        void reset() {
            // no state: every occurrence violates
        }
    }

    private static final class PrecedenceCheck extends EventCheck {
        private final Precedence p;
        private boolean seen;

        PrecedenceCheck(Precedence p) {
            super(p.then());
            this.p = p;
        }

        @Override
        Verdict.Violated step(LogRecord r, long ticks) {
            if (p.first().matches(r)) {
                seen = true;
            } else if (!seen && p.then().matches(r)) {
                return new Verdict.Violated(r.line(), r.time(), null, null,
                        p.then().describe() + " before any " + p.first().describe());
            }
            return null;
        }

        @Override
        void reset() {
            seen = false;
        }
    }
}
