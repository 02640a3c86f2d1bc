package dev.predmon.property;

import dev.predmon.parse.Decimals;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * What a set of logs holds, by name: each distinct message (kind, protocol, command, ports) with the first arguments
 * and replies it came with, and whether a reply of it was a number. What {@link UnseenNames} checks a property's
 * names against. Bounded: at most {@value #MAX_VALUES} distinct arguments and replies are kept per message; beyond
 * that a value not kept cannot be said never to have come.
 */
public final class Vocabulary {

    /** Distinct arguments, and replies, kept per message. */
    static final int MAX_VALUES = 1000;

    /** One message: a record without its argument and reply. */
    record Message(RecordKind kind, String protocol, String command, String from, String to) {

        /** A record of this message, with the given argument and reply: what a matcher is asked about. */
        LogRecord record(String argument, String reply) {
            return new LogRecord(0, 0, "DEBUG", kind, from, to, protocol, command, argument, reply);
        }
    }

    /** What one message came with. */
    static final class Values {
        final Set<String> arguments = new LinkedHashSet<>();
        final Set<String> replies = new LinkedHashSet<>();
        boolean argumentsFull;
        boolean repliesFull;
        boolean number;

        private static boolean add(Set<String> values, String v) {
            if (values.size() >= MAX_VALUES) {
                return !values.contains(v);
            }
            values.add(v);
            return false;
        }
    }

    private final Map<Message, Values> messages = new HashMap<>();
    private long records;

    /** Takes the next record of a log. */
    public void accept(LogRecord r) {
        if (r.kind() == RecordKind.UNKNOWN) {
            return;
        }
        records++;
        Values v = messages.computeIfAbsent(new Message(r.kind(), r.protocol(), r.command(), r.from(), r.to()),
                m -> new Values());
        String argument = r.arguments().trim();
        String reply = r.reply().trim();
        v.argumentsFull |= Values.add(v.arguments, argument);
        v.repliesFull |= Values.add(v.replies, reply);
        if (!v.number && r.kind() == RecordKind.REPLY && !Double.isNaN(Decimals.parse(reply))) {
            v.number = true;
        }
    }

    /** Records taken (ticks, commands and replies). */
    public long records() {
        return records;
    }

    /** Every message seen, with its values. */
    Map<Message, Values> messages() {
        return messages;
    }

    /** The distinct non-empty values of one field over every message, sorted: protocols, commands or ports. */
    Set<String> names(java.util.function.Function<Message, String> field) {
        Set<String> names = new TreeSet<>();
        for (Message m : messages.keySet()) {
            String name = field.apply(m);
            if (!name.isEmpty()) {
                names.add(name);
            }
        }
        return names;
    }

    /** The messages {@code match} picks records of, whatever their values ({@link RecordMatch#message}). */
    List<Message> matching(RecordMatch match) {
        RecordMatch m = match.message();
        return messages.keySet().stream().filter(x -> m.matches(x.record("", ""))).toList();
    }

    /** Whether a record of {@code messages} came with one of {@code wanted} as its argument (or reply). */
    boolean anyValue(Collection<Message> of, List<String> wanted, boolean replies) {
        for (Message m : of) {
            Set<String> seen = replies ? messages.get(m).replies : messages.get(m).arguments;
            if (wanted.stream().anyMatch(seen::contains)) {
                return true;
            }
        }
        return false;
    }

    /** Whether every value of {@code of} was kept, so that a value not among them never came. */
    boolean allKept(Collection<Message> of, boolean replies) {
        return of.stream().map(messages::get).noneMatch(v -> replies ? v.repliesFull : v.argumentsFull);
    }

    /** The values {@code of} came with, sorted. */
    Set<String> values(Collection<Message> of, boolean replies) {
        Set<String> all = new TreeSet<>();
        of.forEach(m -> all.addAll(replies ? messages.get(m).replies : messages.get(m).arguments));
        all.remove("");
        return all;
    }

    /** Whether a reply of {@code of} was a number. */
    boolean anyNumber(Collection<Message> of) {
        return of.stream().anyMatch(m -> messages.get(m).number);
    }
}
