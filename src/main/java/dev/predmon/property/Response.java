package dev.predmon.property;

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
 * @param within    the deadline
 */
public record Response(String id, String name, String action, Scope scope, Event trigger, Condition condition,
                       Event response, Event cancelledBy, Deadline within) implements Property {

    public Response {
        if ((trigger == null) == (condition == null)) {
            throw new IllegalArgumentException("a response has exactly one of a trigger event and a condition");
        }
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
