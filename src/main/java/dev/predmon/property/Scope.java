package dev.predmon.property;

/**
 * Where a property is checked. {@link #GLOBAL}: the whole run. Otherwise only between an occurrence of {@code from}
 * and the next occurrence of {@code until}, both records included (Dwyer's "between Q and R"); each such segment
 * starts the property afresh, and a response still pending when the segment ends is violated there. A segment that
 * the run's end leaves open is judged as an unfinished run. A violation stays: the property is violated for the run.
 *
 * @param from  opens a segment, or null for the whole run
 * @param until closes it, or null for the whole run
 */
public record Scope(Event from, Event until) {

    /** The whole run. */
    public static final Scope GLOBAL = new Scope(null, null);

    public Scope {
        if ((from == null) != (until == null)) {
            throw new IllegalArgumentException("a scope has both a from and an until event, or neither");
        }
    }

    /** Whether this is the whole run. */
    public boolean global() {
        return from == null;
    }
}
