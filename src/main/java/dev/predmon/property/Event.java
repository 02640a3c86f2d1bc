package dev.predmon.property;

import dev.predmon.parse.LogRecord;

import java.util.List;
import java.util.stream.Collectors;

/**
 * An event of a property: a record that matches any of {@code alternatives} (navigation ends: a {@code getStatus}
 * reply SUCCESS, or a {@code halt}).
 */
public record Event(List<RecordMatch> alternatives) {

    public Event {
        if (alternatives.isEmpty()) {
            throw new IllegalArgumentException("an event needs at least one record matcher");
        }
        alternatives = List.copyOf(alternatives);
    }

    /** The event of one record matcher. */
    public static Event of(RecordMatch match) {
        return new Event(List.of(match));
    }

    /** Whether {@code r} is this event. */
    public boolean matches(LogRecord r) {
        for (int i = 0; i < alternatives.size(); i++) {
            if (alternatives.get(i).matches(r)) {
                return true;
            }
        }
        return false;
    }

    /** The messages this event picks records of, whatever their argument and reply ({@link RecordMatch#message}). */
    public Event messages() {
        return new Event(alternatives.stream().map(RecordMatch::message).distinct().toList());
    }

    /**
     * What tells that this event could have come, for a property that holds while it does not (an absence, a
     * precedence's {@code then}): per alternative, its message with any argument and reply when it names a value
     * ({@code GoTo/getStatus reply} for {@code GoTo/getStatus reply 3}), else any message of its component (its
     * protocol and ports: {@code ArmService/any message} for an {@code ArmService/emergencyStop command}).
     */
    public Event evidence() {
        return new Event(alternatives.stream().map(m -> m.arguments() != null || m.replies() != null ? m.message()
                : new RecordMatch(null, m.protocol(), null, m.from(), m.to(), null, null)).distinct().toList());
    }

    /** In an operator's words, alternatives joined by {@code or}: {@code getStatus 2 or halt}. */
    public String brief() {
        return alternatives.stream().map(RecordMatch::brief).collect(Collectors.joining(" or "));
    }

    /** In a user's words, alternatives joined by {@code or}. */
    public String describe() {
        return alternatives.stream().map(RecordMatch::describe).collect(Collectors.joining(" or "));
    }
}
