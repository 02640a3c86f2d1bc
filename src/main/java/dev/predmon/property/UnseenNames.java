package dev.predmon.property;

import dev.predmon.parse.RecordKind;
import org.apache.commons.text.similarity.LevenshteinDistance;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.function.Function;

/**
 * The names of properties that no log holds: a misspelt command ({@code getStatsu}), port ({@code ...Clinet}),
 * protocol or reply, each pointed at by its key in the abstraction file ({@code properties[2].event.command}) with the
 * nearest names that do occur (Levenshtein distance over the names the logs hold, {@link Vocabulary}).
 *
 * <p>Every record matcher of a property is checked: each of its names on its own (protocol, command, ports), then
 * that some record is all of them together, then that one came with its argument and reply. An absence's event is
 * checked to its message only: that its value never came is the absence holding, not a typo. Of an event of several
 * alternatives, each name is checked, and the event must have come as one of them; an alternative whose names occur
 * but that never came (a {@code getStatus} reply {@code 4} where every navigation replied {@code 2}) is none. A
 * name that no log holds is told whether it is misspelt or only never came in these logs: the logs cannot tell.
 */
public final class UnseenNames {

    /** Nearest names offered, at most. */
    private static final int NEAREST = 3;
    /** The shortest name offered its nearest names. */
    private static final int MIN_NEAR = 3;

    /**
     * A name no log holds.
     *
     * @param index    the property's position in the file's {@code properties}
     * @param property its id
     * @param key      where the name is: {@code properties[2].event.command}
     * @param given    the name no log holds ({@code getStatsu}), or the matcher's words when its names occur but
     *                 never together
     * @param what     what no log holds, with the nearest names that occur
     */
    public record Problem(int index, String property, String key, String given, String what) {

        /**
         * One line: {@code properties[2].event.command (no-abort): 'getStatsu' occurs in no log (nearest that occur:
         * getStatus)}.
         */
        public String describe() {
            return key + " (" + property + "): " + what;
        }
    }

    private final Vocabulary seen;
    private final List<Problem> problems = new ArrayList<>();
    /** Problems found so far, those told already for the same name included. */
    private int found;
    private int index;
    private String id;

    private UnseenNames(Vocabulary seen) {
        this.seen = seen;
    }

    /** Every name of {@code properties} (in the file's order) that no record of {@code seen} holds, in order. */
    public static List<Problem> check(List<Property> properties, Vocabulary seen) {
        UnseenNames check = new UnseenNames(seen);
        for (int i = 0; i < properties.size(); i++) {
            check.property(i, properties.get(i));
        }
        return List.copyOf(check.problems);
    }

    private void property(int i, Property p) {
        index = i;
        id = p.id();
        String at = "properties[" + i + "]";
        if (!p.scope().global()) {
            event(p.scope().from(), at + ".scope.from", true);
            event(p.scope().until(), at + ".scope.until", true);
        }
        if (p instanceof Bound b) {
            value(b.value(), at + ".value");
        } else if (p instanceof Absence a) {
            event(a.event(), at + ".event", false); // its value never coming is the property holding
        } else if (p instanceof Response r) {
            if (r.trigger() != null) {
                event(r.trigger(), at + ".trigger", true);
            } else {
                value(r.condition().value(), at + ".trigger.value");
            }
            event(r.response(), at + ".response", true);
            if (r.cancelledBy() != null) {
                event(r.cancelledBy(), at + ".cancelledBy", true);
            }
            if (r.within().counted() != null) {
                event(r.within().counted(), at + ".within.of", true);
            }
        } else if (p instanceof Precedence q) {
            event(q.first(), at + ".first", true);
            event(q.then(), at + ".then", true);
        }
    }

    /** An event at {@code at}; {@code values}: whether its arguments and replies must have come too. */
    private void event(Event e, String at, boolean values) {
        List<RecordMatch> alternatives = e.alternatives();
        int before = found;
        for (int k = 0; k < alternatives.size(); k++) {
            names(alternatives.get(k), alternatives.size() == 1 ? at : at + "[" + k + "]");
        }
        if (found > before) {
            return;
        }
        if (alternatives.size() == 1) {
            together(alternatives.get(0), at, values);
        } else if (alternatives.stream().noneMatch(m -> came(m, values))) {
            add(at, e.describe(), "no record is any of " + e.describe() + ", though each name occurs");
        }
    }

    /** Whether a record of {@code m} came (with its argument and reply, when {@code values}). */
    private boolean came(RecordMatch m, boolean values) {
        List<Vocabulary.Message> messages = seen.matching(m);
        if (messages.isEmpty() || !values) {
            return !messages.isEmpty();
        }
        return (m.replies() == null || !seen.allKept(messages, true) || seen.anyValue(messages, m.replies(), true))
                && (m.arguments() == null || !seen.allKept(messages, false)
                || seen.anyValue(messages, m.arguments(), false));
    }

    /** A bound's or a condition's value: its reply must have come, and been a number. */
    private void value(ValueReader v, String at) {
        RecordMatch m = new RecordMatch(RecordKind.REPLY, v.protocol(), v.command(), v.from().isEmpty() ? null
                : v.from(), v.to().isEmpty() ? null : v.to(), null, null);
        int before = found;
        names(m, at);
        if (found > before) {
            return;
        }
        List<Vocabulary.Message> messages = seen.matching(m);
        if (messages.isEmpty()) {
            add(at, m.describe(), "no record matches " + m.describe() + ": each name occurs, never together");
        } else if (!seen.anyNumber(messages)) {
            add(at, m.describe(), "no reply of " + m.describe() + " is a number (replies that occur: "
                    + some(seen.values(messages, true)) + ")");
        }
    }

    /** Each name of {@code m} on its own. */
    private void names(RecordMatch m, String at) {
        if (m.protocol() != null && !seen.names(Vocabulary.Message::protocol).contains(m.protocol())
                && seen.messages().keySet().stream().noneMatch(x -> x.protocol().isEmpty())) {
            add(at + ".protocol", m.protocol(), unseen(m.protocol(), seen.names(Vocabulary.Message::protocol),
                    "protocol"));
        }
        if (m.command() != null && !seen.names(Vocabulary.Message::command).contains(m.command())) {
            add(at + ".command", m.command(), unseen(m.command(), commandsOf(m.protocol()), "command"));
        }
        if (m.from() != null) {
            port(m.from(), at + ".from", Vocabulary.Message::from,
                    new RecordMatch(null, null, null, m.from(), null, null, null));
        }
        if (m.to() != null) {
            port(m.to(), at + ".to", Vocabulary.Message::to, new RecordMatch(null, null, null, null, m.to(), null,
                    null));
        }
    }

    private void port(String pattern, String at, Function<Vocabulary.Message, String> side, RecordMatch alone) {
        if (seen.matching(alone).isEmpty()) {
            add(at, pattern, unseen(pattern, seen.names(side), "port"));
        }
    }

    /** The commands of {@code protocol} that occur, or every command when it names none that occurs. */
    private Set<String> commandsOf(String protocol) {
        if (protocol != null && seen.names(Vocabulary.Message::protocol).contains(protocol)) {
            return seen.names(x -> protocol.equals(x.protocol()) ? x.command() : "");
        }
        return seen.names(Vocabulary.Message::command);
    }

    /** Names that occur one by one: some record must be all of them, with its argument and reply. */
    private void together(RecordMatch m, String at, boolean values) {
        List<Vocabulary.Message> messages = seen.matching(m);
        if (messages.isEmpty()) {
            add(at, m.message().describe(), "no record matches " + m.message().describe()
                    + ": each name occurs, never together");
            return;
        }
        if (!values) {
            return;
        }
        if (m.replies() != null && seen.allKept(messages, true) && !seen.anyValue(messages, m.replies(), true)) {
            String given = String.join("|", m.replies());
            add(at + ".reply", given, unseen(given, seen.values(messages, true), "reply"));
        }
        if (m.arguments() != null && seen.allKept(messages, false)
                && !seen.anyValue(messages, m.arguments(), false)) {
            String given = String.join("|", m.arguments());
            add(at + ".argument", given, unseen(given, seen.values(messages, false), "argument"));
        }
    }

    /** A problem, unless the property's same name was told already (a trigger that is also the counted event). */
    private void add(String key, String given, String what) {
        found++;
        if (problems.stream().noneMatch(p -> p.index() == index && p.given().equals(given))) {
            problems.add(new Problem(index, id, key, given, what));
        }
    }

    /**
     * {@code 'getStatsu' occurs in no log (nearest that occur: getStatus, getState)}; without a near one, the names
     * that occur.
     */
    static String unseen(String given, Set<String> names, String what) {
        // a short value (a status code, 1 for 0) is near any other: the values that occur say more
        List<String> near = given.length() < MIN_NEAR ? List.of() : nearest(given, names);
        return "'" + given + "' occurs in no log (" + (!near.isEmpty() ? "nearest that occur: " + String.join(", ", near)
                : names.isEmpty() ? "no " + what + " occurs" : "those that occur: " + some(names)) + ")";
    }

    /**
     * Up to {@value #NEAREST} of {@code names} within a third of the length of {@code given} (2 at least), nearest
     * first.
     */
    static List<String> nearest(String given, Set<String> names) {
        LevenshteinDistance distance = new LevenshteinDistance(Math.max(2, given.length() / 3));
        record Near(String name, int distance) {
        }
        // ties: the same length first (a transposition, getStatsu for getStatus, keeps it), then by name
        return names.stream().map(n -> new Near(n, distance.apply(given, n))).filter(n -> n.distance() >= 0)
                .sorted(Comparator.comparingInt(Near::distance)
                        .thenComparingInt(n -> Math.abs(n.name().length() - given.length())).thenComparing(Near::name))
                .limit(NEAREST).map(Near::name).toList();
    }

    /** A few names, and how many more. */
    private static String some(Set<String> names) {
        List<String> first = names.stream().limit(5).toList();
        return String.join(", ", first) + (names.size() > first.size() ? " and " + (names.size() - first.size())
                + " more" : "");
    }
}
