package dev.predmon.abstraction;

import dev.predmon.abstraction.Definition.Drop;
import dev.predmon.parse.Decimals;
import dev.predmon.parse.Glob;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The compiled drop filters and rules of an abstraction: what {@link Abstraction#classify} makes of a record.
 *
 * <p>Most of the decision depends only on a record's ports, protocol, command and arguments, which repeat on every
 * record of a connection: whether it is dropped, which rule takes it, its channel, a command's input symbol. That
 * part is decided once per distinct combination and remembered in a small table ({@link Route}); only what depends
 * on a reply's value (its symbol, by the rule's ranges or values) is looked at for every record. Matching the drop
 * globs and rules anew for every record was most of the classification's time on a large log.
 *
 * <p>Immutable apart from caches, and thread-safe: threads reading logs in parallel share one instance. A table slot
 * holds a complete immutable {@link Route} (final fields) or another one, and a route is only used after the strings
 * it was made for are compared with the record's.
 */
final class Rules {

    /** Classifications carry no state when dropped: one instance serves every record. */
    static final Classification DROPPED = new Classification.Dropped();
    private static final int ROUTES = 256;
    private static final int PROBES = 4;

    /** A compiled rule; {@code input} and reply symbols may still contain {@code {loc}}. */
    // An array for the loop over a rule's replies, which runs for every reply record; rules are never compared.
    @SuppressWarnings("ArrayRecordComponent")
    private record Rule(String protocol, String command, String client, String input, Reply[] replies,
                        boolean numeric) {
        boolean usesLocation() {
            if (input.contains(Definition.LOC)) {
                return true;
            }
            for (Reply r : replies) {
                if (r.located) {
                    return true;
                }
            }
            return false;
        }
    }

    /**
     * A compiled reply: exactly one of {@code any}, {@code values}, {@code band} is set; {@code located} when its
     * symbol contains {@code {loc}} (looked up once here, not at every reply it maps).
     */
    private record Reply(boolean any, Set<String> values, Band band, String symbol, boolean located) {
        /** @param number the value parsed once per record, NaN when it is not a decimal number */
        boolean matches(String value, double number) {
            if (any) {
                return true;
            }
            if (values != null) {
                return values.contains(value);
            }
            return !Double.isNaN(number) && band.contains(number);
        }
    }

    /**
     * What a record's identity decides, for the strings it was made for (a reply's value is not among them).
     *
     * @param decided  the classification when it does not depend on the record beyond them (dropped; a command
     *                 without rule or about an unknown location), else null
     * @param rule     the rule taking the record, null if none
     * @param channel  the record's channel
     * @param input    a command's input symbol, {@code {loc}} replaced; null for replies
     * @param location a reply's location abbreviation when its arguments name one, else null
     * @param client   a reply's location abbreviation by its client port, else null (used when neither the arguments
     *                 nor the reply name one)
     * @param arguments    the arguments it was made for, or null when the decision does not depend on them
     * @param commandReply a command's reply field it was made for, or null when the decision does not depend on it
     */
    private record Route(RecordKind kind, String from, String to, String protocol, String command, String arguments,
                         String commandReply, Classification decided, Rule rule, Channel channel, String input,
                         String location, String client) {

        boolean isFor(LogRecord r) {
            return kind == r.kind() && same(from, r.from()) && same(to, r.to()) && same(protocol, r.protocol())
                    && same(command, r.command())
                    && (arguments == null || same(arguments, r.arguments()))
                    && (commandReply == null || same(commandReply, r.reply()));
        }

        private static boolean same(String a, String b) {
            return Objects.equals(a, b);
        }
    }

    private final List<Drop> drop;
    private final Map<String, String> locations;
    /** Rules by command, in file order. */
    private final Map<String, List<Rule>> rulesByCommand;
    /** Symbols with {@code {loc}} already replaced, by template and abbreviation (the set is small and fixed). */
    private final Map<String, Map<String, String>> expanded = new ConcurrentHashMap<>();
    private final Route[] routes = new Route[ROUTES];

    Rules(Definition definition) {
        this.drop = definition.drop();
        this.locations = definition.locations();
        Map<String, List<Rule>> byCommand = new HashMap<>();
        for (Definition.Rule r : definition.rules()) {
            List<Reply> replies = new ArrayList<>();
            for (Definition.Reply p : r.replies()) {
                replies.add(new Reply(p.any(), p.values() == null ? null : Set.copyOf(p.values()), p.range(),
                        p.symbol(), p.symbol().contains(Definition.LOC)));
            }
            // An array, not a List: rules have one to a dozen replies, and List.of's two classes (up to two elements,
            // more) made the JIT recompile classify's reply loop whenever the other kind came along.
            byCommand.computeIfAbsent(r.command(), k -> new ArrayList<>()).add(new Rule(r.protocol(), r.command(),
                    r.client(), r.input(), replies.toArray(new Reply[0]), replies.stream().anyMatch(x -> x.band() != null)));
        }
        byCommand.replaceAll((k, v) -> List.copyOf(v));
        this.rulesByCommand = Map.copyOf(byCommand);
    }

    /** See {@link Abstraction#classify}. */
    Classification classify(LogRecord r) {
        RecordKind kind = r.kind();
        if (kind != RecordKind.COMMAND && kind != RecordKind.REPLY) {
            return DROPPED;
        }
        Route route = route(r);
        if (route.decided != null) {
            return route.decided;
        }
        if (kind == RecordKind.COMMAND) {
            return new Classification.Mapped(new AbstractEvent(Direction.INPUT, route.input, route.channel, r));
        }
        Rule rule = route.rule;
        if (rule == null) {
            return unmapped(r, UnmappedMessage.Kind.REPLY, r.reply());
        }
        String value = r.reply();
        double number = rule.numeric ? Decimals.parse(value) : Double.NaN;
        Reply taken = null;
        for (Reply p : rule.replies) {
            if (p.matches(value, number)) {
                taken = p;
                break;
            }
        }
        if (taken == null) {
            return unmapped(r, UnmappedMessage.Kind.REPLY, r.reply());
        }
        String template = taken.symbol;
        if (taken.located) {
            String abbreviation = route.location != null ? route.location : locations.get(r.reply().trim());
            if (abbreviation == null) {
                abbreviation = route.client;
            }
            if (abbreviation == null) {
                return unmapped(r, UnmappedMessage.Kind.REPLY_LOCATION, locationCandidate(r));
            }
            template = expand(template, abbreviation);
        }
        return new Classification.Mapped(new AbstractEvent(Direction.OUTPUT, template, route.channel, r, number));
    }

    /** The route of {@code r}'s strings: remembered, or decided now and remembered. */
    // The ordinal only mixes the record's kind into a hash, where any fixed number per kind would do.
    @SuppressWarnings("EnumOrdinal")
    private Route route(LogRecord r) {
        int h = (r.from().hashCode() * 31 + r.to().hashCode()) * 31 + r.command().hashCode() + r.kind().ordinal();
        h ^= h >>> 16;
        h *= 0x45d9f3b;
        int home = (h ^ (h >>> 16)) & (ROUTES - 1);
        // Up to PROBES neighbouring slots: two busy connections whose hashes collide must not evict each other.
        int free = -1;
        for (int k = 0; k < PROBES; k++) {
            int slot = (home + k) & (ROUTES - 1);
            Route known = routes[slot];
            if (known == null) {
                free = free < 0 ? slot : free;
            } else if (known.isFor(r)) {
                return known;
            }
        }
        Route made = decide(r);
        routes[free < 0 ? home : free] = made;
        return made;
    }

    private Route decide(LogRecord r) {
        boolean command = r.kind() == RecordKind.COMMAND;
        Channel channel = Channel.of(r);
        for (int i = 0; i < drop.size(); i++) {
            if (dropped(drop.get(i), r)) {
                return route(r, false, DROPPED, null, channel, null, null, null);
            }
        }
        Rule rule = null;
        List<Rule> candidates = rulesByCommand.getOrDefault(r.command(), List.of());
        for (Rule x : candidates) {
            if ((r.protocol().isEmpty() || x.protocol.equals(r.protocol()))
                    && (x.client == null || glob(x.client, channel.client()))) {
                rule = x;
                break;
            }
        }
        if (rule == null) {
            Classification unmapped = command ? unmapped(r, UnmappedMessage.Kind.COMMAND, "") : null;
            return route(r, false, unmapped, null, channel, null, null, null);
        }
        if (!command) {
            return route(r, rule.usesLocation(), null, rule, channel, null, locationByArguments(r),
                    locations.get(lastSegment(channel.client())));
        }
        String input = rule.input;
        if (input.contains(Definition.LOC)) {
            String abbreviation = location(r);
            if (abbreviation == null) {
                Classification unknown = unmapped(r, UnmappedMessage.Kind.COMMAND_LOCATION, locationCandidate(r));
                return route(r, true, unknown, rule, channel, null, null, null);
            }
            input = expand(input, abbreviation);
            return route(r, true, null, rule, channel, input, null, null);
        }
        return route(r, false, null, rule, channel, input, null, null);
    }

    /** @param byLocation whether the decision depends on the location the record names (arguments, reply) */
    private static Route route(LogRecord r, boolean byLocation, Classification decided, Rule rule, Channel channel,
                               String input, String location, String client) {
        boolean command = r.kind() == RecordKind.COMMAND;
        return new Route(r.kind(), r.from(), r.to(), r.protocol(), r.command(), byLocation ? r.arguments() : null,
                byLocation && command ? r.reply() : null, decided, rule, channel, input, location, client);
    }

    private String expand(String template, String abbreviation) {
        Map<String, String> byLocation = expanded.get(template);
        String known = byLocation == null ? null : byLocation.get(abbreviation);
        return known != null ? known
                : expanded.computeIfAbsent(template, t -> new ConcurrentHashMap<>())
                .computeIfAbsent(abbreviation, a -> template.replace(Definition.LOC, a));
    }

    /** {@code r} is a message of this kind that no rule maps, told apart by {@code detail}. */
    private static Classification unmapped(LogRecord r, UnmappedMessage.Kind kind, String detail) {
        return new Classification.Unmapped(new UnmappedMessage(r.protocol(), r.command(), kind, detail));
    }

    private static boolean dropped(Drop d, LogRecord r) {
        return (d.kind() == null || d.kind().equalsIgnoreCase(r.kind().name()))
                && (d.from() == null || glob(d.from(), r.from()))
                && (d.to() == null || glob(d.to(), r.to()))
                && (d.protocol() == null || glob(d.protocol(), r.protocol()))
                && (d.command() == null || glob(d.command(), r.command()));
    }

    /**
     * Whether {@code text} matches {@code pattern}, where {@code *} stands for any characters (possibly none) and
     * everything else for itself: BT-to-skill ports are {@code /<Skill>/BT_rpc/client}, one per skill, and the
     * older log format has no Protocol line to drop them by.
     */
    static boolean glob(String pattern, String text) {
        return Glob.matches(pattern, text);
    }

    /**
     * The abbreviation of the location {@code r} is about: named by its arguments, else by its reply, else by the
     * last segment of its client port; {@code null} if none.
     */
    private String location(LogRecord r) {
        String known = locationByArguments(r);
        if (known == null) {
            known = locations.get(r.reply().trim());
        }
        if (known == null) {
            known = locations.get(lastSegment(Channel.of(r).client()));
        }
        return known;
    }

    private String locationByArguments(LogRecord r) {
        String args = r.arguments().trim();
        String known = locations.get(args);
        if (known == null && !args.isEmpty()) {
            // The older format prints all arguments space separated; the location is the first.
            known = locations.get(args.split("\\s+", 2)[0]);
        }
        return known;
    }

    private static String locationCandidate(LogRecord r) {
        return !r.arguments().isBlank() ? r.arguments().trim() : lastSegment(Channel.of(r).client());
    }

    private static String lastSegment(String port) {
        return port.substring(port.lastIndexOf('/') + 1);
    }
}
