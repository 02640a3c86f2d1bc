package dev.predmon.property;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

/**
 * Bounded response: after a trigger, a response comes within a deadline, {@code historically(not(not response
 * since[>T] trigger))} as MOON writes it. The trigger is an event ({@code goTo}) or a condition becoming true
 * ({@code battery < 30}); exactly one of {@code trigger} and {@code condition} is given.
 *
 * <p>A response may last: with {@code cancelledBy}, it holds from an occurrence of {@code response} until the next
 * occurrence of {@code cancelledBy} (SCOPE's destination: a {@code goTo} to the charging station holds until a
 * {@code goTo} elsewhere), and a trigger while it holds opens nothing; the trigger is then
 * {@code trigger and not (not cancelledBy since response)}. Without it a response is an instant.
 *
 * <p>An obligation opens at a trigger and is discharged by any response after it; a trigger while one is open does
 * not open another (the earliest unanswered trigger is the one that must be answered in time). The deadline passes
 * as soon as a record arrives beyond it: a tick more than {@code T} ticks after the trigger's, a time more than
 * {@code T} seconds after it, or the {@code K+1}-th occurrence of the counted event. A response on that record comes
 * too late. At the end of a log that stops with an obligation open, the verdict is pending: the deadline was not due.
 *
 * @param trigger   the event that opens an obligation, or null when {@code condition} does
 * @param condition the condition whose becoming true opens one, or null
 * @param response  the event that discharges it
 * @param cancelledBy the event that ends a lasting response, or null when a response is an instant
 * <p>With {@code per}, each trigger opens an obligation of its own instance (the client connection or the argument
 * of its record: one navigation per destination, one action goal per goal id), and a response, or a counted
 * occurrence, acts on the obligation of its own instance only: a navigation that preempts another while that one is
 * still running (a {@code goTo} to the charging station before the {@code halt} of the way to the kitchen) owes its
 * own end, which the halt of the other does not give. Within one instance the earliest unanswered trigger is still
 * the one that must be answered in time.
 *
 * @param within    the deadline
 * @param per       what tells a trigger's instance, or null: one obligation at a time for the whole run
 */
public record Response(String id, String name, String action, Scope scope, Event trigger, Condition condition,
                       Event response, Event cancelledBy, Deadline within, Per per) implements Property {

    /** What tells the instances of a response apart: which record field names the obligation a record acts on. */
    public enum Per {
        /** The client's port: a command's {@code From}, a reply's {@code To}. */
        CLIENT("client"),
        /** The record's first argument. */
        ARGUMENT("argument");

        /** The key of the abstraction file. */
        public final String key;

        Per(String key) {
            this.key = key;
        }

        /** The instance {@code r} names. */
        public String of(LogRecord r) {
            return this == ARGUMENT ? r.arguments() : r.kind() == RecordKind.REPLY ? r.to() : r.from();
        }
    }

    public Response {
        if ((trigger == null) == (condition == null)) {
            throw new IllegalArgumentException("a response has exactly one of a trigger event and a condition");
        }
        if (per != null && (trigger == null || cancelledBy != null)) {
            throw new IllegalArgumentException("'per' needs a trigger event and no 'cancelledBy'");
        }
    }

    /** A response with one obligation at a time for the whole run. */
    public Response(String id, String name, String action, Scope scope, Event trigger, Condition condition,
                    Event response, Event cancelledBy, Deadline within) {
        this(id, name, action, scope, trigger, condition, response, cancelledBy, within, null);
    }

    @Override
    public String kind() {
        return "response";
    }

    /** The trigger in an operator's words, without kinds and ports ({@code goTo}). */
    public String briefTrigger() {
        return trigger != null ? trigger.brief() : condition.describe();
    }

    /** The trigger in a user's words. */
    public String describeTrigger() {
        return trigger != null ? trigger.describe() : condition.describe();
    }
}
