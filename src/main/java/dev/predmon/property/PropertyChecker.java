package dev.predmon.property;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.List;

/**
 * Checks every property on one run, record by record, with constant state per property: the safety monitor of a
 * run. Each property's first violation is told to the listener as it happens and stays its verdict for the run;
 * {@link #reset()} starts the next run.
 *
 * <p>Scopes: a property with a scope is checked from an occurrence of its {@code from} event (that record
 * included) to the next occurrence of its {@code until} event (included, unless it is the opening record); each
 * segment starts the property's check afresh and a response owed when a segment closes is violated there.
 *
 * <p>Evidence: a property that is neither violated nor pending holds only when something it speaks of occurred in
 * the run, within its scope: a bound's value was read; a record that tells an absence's (or a precedence's
 * {@code then}) event could have come, its message with another value or, for an event that names no value, any
 * message of its component ({@link Event#evidence}); a response's trigger, whatever its value (or a reading of its
 * condition's value).
 * Otherwise its verdict is {@link Verdict.NoEvidence}: a misspelt name is never "holds".
 */
public final class PropertyChecker implements PropertyView {

    /** Told each property's first violation in a run. */
    @FunctionalInterface
    public interface Listener {
        /**
         * A property is violated for the first time in the run.
         *
         * @param index    the property's position in the checker's list
         * @param property the property
         * @param verdict  its violation
         */
        void violated(int index, Property property, Verdict.Violated verdict);
    }

    /** Told each obligation's end with its property's position. */
    @FunctionalInterface
    public interface ObligationListener {
        /**
         * Property {@code index}'s obligation, opened by the trigger at {@code line}, ended after {@code duration} in
         * its deadline's unit: {@code discharged} when its response came, else let go still pending (a censored
         * duration).
         */
        void closed(int index, Property property, long line, double duration, boolean discharged);
    }

    /** A property with its verdict. */
    public record PropertyVerdict(Property property, Verdict verdict) {
    }

    private final List<Property> properties;
    private final Scope[] scopes;
    private final Check[] checks;
    /** Every value the properties read, each read once per record, whatever the scopes. */
    private final Readings readings;
    /** Per property, its value's slot in {@link #readings} (a bound's), or -1. */
    private final int[] slots;
    private final boolean[] open;
    /** Per property, whether its scope is the whole run, and whether its check reads a value ({@link Check#reads}). */
    private final boolean[] global;
    private final boolean[] reads;
    private final Verdict.Violated[] violated;
    /** Per property, whether the run showed evidence for it ({@link Check#evidences}), and whether its scope opened. */
    private final boolean[] evidenced;
    private final boolean[] opened;
    /** Per property, its verdict without evidence: nothing seen in its scope, and its scope never opened. */
    private final Verdict.NoEvidence[] unseen;
    private final Verdict.NoEvidence[] unopened;
    /** Whether each property is violated now: since a violation, until it holds again or its segment closes. */
    private final boolean[] now;
    /** The violation the last record made of each property that was not violated just before it, or null. */
    private final Verdict.Violated[] made;
    /** Whether the last record's reading of each bound ended its violation. */
    private final boolean[] again;
    private final Listener listener;
    private long ticks;

    public PropertyChecker(List<Property> properties, Listener listener) {
        this.properties = List.copyOf(properties);
        this.listener = listener;
        this.checks = new Check[this.properties.size()];
        this.scopes = new Scope[checks.length];
        this.slots = new int[checks.length];
        this.global = new boolean[checks.length];
        this.reads = new boolean[checks.length];
        this.readings = new Readings(this.properties);
        for (int i = 0; i < checks.length; i++) {
            Property p = this.properties.get(i);
            checks[i] = Check.of(p, readings);
            scopes[i] = p.scope();
            slots[i] = p instanceof Bound b ? readings.slot(b.value()) : -1;
            global[i] = scopes[i].global();
            reads[i] = checks[i].reads();
        }
        this.open = new boolean[checks.length];
        this.violated = new Verdict.Violated[checks.length];
        this.evidenced = new boolean[checks.length];
        this.opened = new boolean[checks.length];
        this.unseen = new Verdict.NoEvidence[checks.length];
        this.unopened = new Verdict.NoEvidence[checks.length];
        for (int i = 0; i < checks.length; i++) {
            unseen[i] = new Verdict.NoEvidence(checks[i].unseen() + (scopes[i].global() ? " in the run"
                    : " within its scope"));
            unopened[i] = scopes[i].global() ? unseen[i] : new Verdict.NoEvidence("its scope never opened: no "
                    + scopes[i].from().describe());
        }
        this.now = new boolean[checks.length];
        this.made = new Verdict.Violated[checks.length];
        this.again = new boolean[checks.length];
    }

    /** Takes the next record of the run. */
    public void accept(LogRecord r) {
        if (r.kind() == RecordKind.TICK) {
            ticks++;
        }
        readings.read(r);
        for (int i = 0; i < checks.length; i++) {
            Check c = checks[i];
            c.reading = Double.NaN;
            c.opened = -1;
            c.triggered = -1;
            c.wordless = now[i] && violated[i] != null; // judge keeps no violation it makes: neither made nor first
            made[i] = null;
            again[i] = false;
            if (violated[i] != null && !reads[i]) {
                continue; // the verdict is final; only a bound still reads its value, for the forecast
            }
            Scope s = scopes[i];
            Verdict.Violated v;
            if (global[i]) {
                v = c.step(r, ticks);
                if (!evidenced[i]) {
                    evidenced[i] = c.evidences(r);
                }
            } else {
                boolean opening = !open[i] && s.from().matches(r);
                if (opening) {
                    open[i] = true;
                    opened[i] = true;
                    c.reset();
                }
                if (!open[i]) {
                    continue;
                }
                v = c.step(r, ticks);
                if (!evidenced[i]) {
                    evidenced[i] = c.evidences(r); // before the segment closes: its closing record is in it
                }
                if (!opening && s.until().matches(r)) {
                    open[i] = false;
                    Verdict.Violated owed = c.close(r);
                    v = v != null ? v : owed;
                    c.reset();
                }
            }
            judge(i, c, v);
            if (!inScope(i) && reads[i]) {
                now[i] = false; // out of its scope a bound cannot be violated: its violation ends with the scope
            }
            if (v != null && violated[i] == null) {
                violated[i] = v;
                listener.violated(i, properties.get(i), v);
            }
        }
    }

    /**
     * What record's step {@code v} does to property {@code i}'s violation now: a violation starts one (told as made
     * when none was up); a bound's reading that holds ends one.
     */
    private void judge(int i, Check c, Verdict.Violated v) {
        if (v != null) {
            made[i] = now[i] ? null : v;
            now[i] = true;
        } else if (now[i] && !Double.isNaN(c.reading)) {
            now[i] = false; // a bound's reading within its bounds: it holds again
            again[i] = true;
        }
    }

    /** Tells {@code listener} how every obligation of a bounded response ends, from now on. */
    public void onObligations(ObligationListener listener) {
        for (int i = 0; i < checks.length; i++) {
            int index = i;
            Property p = properties.get(i);
            checks[i].obligations = (line, duration, discharged) -> listener.closed(index, p, line, duration,
                    discharged);
        }
    }

    /**
     * How long property {@code index}'s open obligation has been pending, in its deadline's unit; NaN when none is
     * open (or the property is no bounded response).
     */
    public double elapsed(int index) {
        return checks[index].elapsed();
    }

    /** The trigger line of property {@code index}'s obligation that {@link #elapsed} tells, -1 when none is open. */
    public long pendingLine(int index) {
        return checks[index].pendingLine();
    }

    /** The line of the trigger whose obligation of property {@code index} the last record opened, or -1. */
    public long opened(int index) {
        return checks[index].opened;
    }

    /** Whether the last record was property {@code index}'s trigger event, 1 or 0; -1 when its check did not ask. */
    public int triggered(int index) {
        return checks[index].triggered;
    }

    /** The value the last record gave property {@code index} (a {@link Bound}), or NaN when it gave none. */
    @Override
    public double reading(int index) {
        return checks[index].reading;
    }

    /**
     * The value the last record carried for bound {@code index} ({@link Bound#valueOf}), whether or not its scope is
     * open; NaN when it carried none (or the property is no bound).
     */
    @Override
    public double value(int index) {
        return slots[index] < 0 ? Double.NaN : readings.value(slots[index]);
    }

    /**
     * Whether property {@code index} is checked now, after the last record: its scope is the whole run, or a segment of
     * it opened and has not closed (a segment's closing record was checked, and the scope is closed after it).
     */
    @Override
    public boolean inScope(int index) {
        return global[index] || open[index];
    }

    /**
     * Whether property {@code index} is violated now, after the last record: a bound from a violating reading until
     * it holds again (its next reading within its bounds) or its scope closes; any other kind from its violation to
     * the end of the run (its verdict is final).
     */
    @Override
    public boolean violatedNow(int index) {
        return now[index];
    }

    /**
     * The violation the last record made of property {@code index} when it was not violated just before (its first
     * in the run, or a bound's next one after it held again), or null.
     */
    public Verdict.Violated violatedAt(int index) {
        return made[index];
    }

    /** Whether the last record's reading of bound {@code index} (within its scope) ended its violation. */
    public boolean holdsAgain(int index) {
        return again[index];
    }

    /**
     * The verdict of property {@code index} on the run so far: violated, pending, holds, or no evidence when nothing it
     * speaks of occurred in its scope yet.
     */
    @Override
    public Verdict verdict(int index) {
        if (violated[index] != null) {
            return violated[index];
        }
        Verdict owed = open[index] || scopes[index].global() ? checks[index].owed() : Verdict.HOLDS;
        if (evidenced[index] || owed instanceof Verdict.Pending) {
            return owed;
        }
        return opened[index] ? unseen[index] : unopened[index];
    }

    /** Every property with its verdict on the run so far, in the checker's order. */
    public List<PropertyVerdict> verdicts() {
        List<PropertyVerdict> all = new ArrayList<>(checks.length);
        for (int i = 0; i < checks.length; i++) {
            all.add(new PropertyVerdict(properties.get(i), verdict(i)));
        }
        return all;
    }

    /** The properties checked, in order. */
    @Override
    public List<Property> properties() {
        return properties;
    }

    /**
     * The run ends, and {@code r} is the first record after it, which begins the next run: a bounded response whose
     * deadline in seconds passed before {@code r} came (a robot frozen through the silence that began the new run) is
     * violated at {@code r}, in this run, and told as every violation is; never dropped with the run.
     */
    public void overdue(LogRecord r) {
        for (int i = 0; i < checks.length; i++) {
            made[i] = null; // a judgement of its own: what the last record made is told already
            again[i] = false;
            if (violated[i] == null && (scopes[i].global() || open[i])) {
                Verdict.Violated v = checks[i].overdue(r);
                if (v != null) {
                    violated[i] = v;
                    made[i] = now[i] ? null : v;
                    now[i] = true;
                    listener.violated(i, properties.get(i), v);
                }
            }
        }
    }

    /**
     * A tick of a log without time stamps lasts {@code seconds} ({@code watch --tick-seconds}): a deadline of T
     * seconds in such a log is T seconds of ticks. NaN, the default: a tick counts as a second.
     */
    public void countTicksAs(double seconds) {
        for (Check c : checks) {
            c.countTicksAs(seconds);
        }
    }

    /** The run ends (a new run, the end of the log): obligations still open are told as censored. */
    public void finish() {
        for (Check c : checks) {
            c.finish();
        }
    }

    /** A new run: every property starts over. */
    public void reset() {
        ticks = 0;
        for (int i = 0; i < checks.length; i++) {
            checks[i].reset();
            open[i] = false;
            violated[i] = null;
            evidenced[i] = false;
            opened[i] = false;
            now[i] = false;
            made[i] = null;
            again[i] = false;
        }
    }
}
