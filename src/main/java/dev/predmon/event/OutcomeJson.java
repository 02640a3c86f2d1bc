package dev.predmon.event;

import dev.predmon.monitor.PropertyOutcome;
import dev.predmon.property.Verdict;

import java.util.List;

/**
 * A run's outcome as JSON, per property and worst first: {@code worst} the id of its worst property and {@code state}
 * that property's state ({@code violated}, {@code warned}, {@code pending}, {@code not observed}, ..., {@code holds});
 * {@code violated} the ids of the properties it violated and {@code warned} of those it warned of (a violated one
 * included when it was warned), each worst first; {@code properties} every property, worst first.
 */
public record OutcomeJson(String worst, String state, List<String> violated, List<String> warned,
                          List<Entry> properties) {

    /**
     * One property's outcome.
     *
     * @param property its id
     * @param state    {@link PropertyOutcome#state()}
     * @param line     the line of its violation, or null
     * @param warnedAt the line of its first warning, or null
     * @param lead     violation time minus warning time, for a violation warned of before it, else null
     */
    public record Entry(String property, String state, Long line, Long warnedAt, Double lead) {
    }

    /** The outcome of {@code worstFirst} ({@link PropertyOutcome#of}); null for a run with no property. */
    public static OutcomeJson of(List<PropertyOutcome> worstFirst) {
        if (worstFirst.isEmpty()) {
            return null;
        }
        List<String> violated = worstFirst.stream().filter(p -> p.verdict() instanceof Verdict.Violated)
                .map(PropertyOutcome::id).toList();
        List<String> warned = worstFirst.stream().filter(p -> p.warning() != null).map(PropertyOutcome::id).toList();
        List<Entry> entries = worstFirst.stream().map(p -> new Entry(p.id(), p.state(),
                p.verdict() instanceof Verdict.Violated v ? v.line() : null,
                p.warning() == null ? null : p.warning().line(), p.lead().orElse(null))).toList();
        PropertyOutcome w = worstFirst.get(0);
        return new OutcomeJson(w.id(), w.state(), violated, warned, entries);
    }
}
