package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.Classification;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * The interface messages of a log that no abstraction rule maps, told by command. The abstraction names each kind
 * apart ({@code GoTo/getCurrentPose reply '-6.19;0.55'}), so a real robot's log read with another robot's abstraction
 * has thousands of kinds, one per pose; a person needs to know which commands, how many messages, and why. This
 * class groups them ({@link #lines}: at most {@value #MAX_LINES} lines) and says when they show that the
 * abstraction, and so the models, do not fit the log at all ({@link #misfit}), with the likely fix.
 */
public final class UnmappedMessages {

    /** At most this many lines say which commands were not mapped; one more counts the rest. */
    public static final int MAX_LINES = 10;

    /**
     * One command's messages no rule maps.
     *
     * @param command   {@code Protocol/command}
     * @param messages  how many
     * @param noRule    whether the abstraction has no rule for the command at all
     * @param locations the locations its messages name that the abstraction does not know
     * @param replies   distinct reply values no reply of its rule takes
     * @param more      whether more kinds came than are told apart ({@link UnmappedCounts}): {@code replies} is
     *                  a lower bound
     */
    public record Group(String command, long messages, boolean noRule, TreeSet<String> locations, long replies,
                        boolean more) {

        /** {@code GoTo/goTo (4 messages): about a location the abstraction does not know: 'user'}. */
        public String describe() {
            List<String> why = new ArrayList<>();
            if (noRule) {
                why.add("no rule for this command");
            }
            if (!locations.isEmpty()) {
                why.add("about locations it does not know: '" + String.join("', '", locations) + "'");
            }
            if (replies > 0) {
                why.add(replies + " distinct " + (replies == 1 ? "reply" : "replies") + " no rule takes");
            }
            if (more) {
                why.add("more distinct messages than are told apart");
            }
            return command + " (" + messages + (messages == 1 ? " message" : " messages") + "): "
                    + String.join("; ", why);
        }
    }

    private UnmappedMessages() {
    }

    /** The command a group counts {@code m} under: {@code GoTo/goTo}, or the text of every other command. */
    private static String command(UnmappedMessage m) {
        return m.kind() == UnmappedMessage.Kind.OTHER_COMMANDS ? m.text() : m.name();
    }

    /** The messages by command, the commands with most messages first. */
    public static List<Group> groups(Map<UnmappedMessage, Long> unmapped) {
        Map<String, long[]> counts = new LinkedHashMap<>(); // messages, no rule (0/1), distinct replies, more (0/1)
        Map<String, TreeSet<String>> locations = new LinkedHashMap<>();
        unmapped.forEach((kind, n) -> {
            String command = command(kind);
            long[] c = counts.computeIfAbsent(command, k -> new long[4]);
            locations.computeIfAbsent(command, k -> new TreeSet<>());
            c[0] += n;
            switch (kind.kind()) {
                case OTHER_VALUES, OTHER_COMMANDS -> c[3] = 1;
                case COMMAND_LOCATION, REPLY_LOCATION -> locations.get(command).add(kind.location());
                case COMMAND -> c[1] = 1;
                case REPLY -> c[2]++;
            }
        });
        List<Group> groups = new ArrayList<>();
        counts.forEach((command, c) -> {
            // a reply of a command without rule has no rule either: it says nothing more about the command
            long replies = c[1] == 1 ? 0 : c[2];
            groups.add(new Group(command, c[0], c[1] == 1, locations.get(command), replies, c[3] == 1));
        });
        groups.sort(Comparator.comparingLong(Group::messages).reversed().thenComparing(Group::command));
        return groups;
    }

    /**
     * Whether a message of this kind is the robot doing something the models never saw, rather than a component the
     * abstraction leaves out talking (a camera): it names a location the abstraction does not know, or it is a command
     * or a reply of a component the abstraction maps that no rule takes. The trace misses a step there.
     */
    public static boolean novelty(UnmappedMessage kind, Abstraction abstraction) {
        return kind.location() != null || abstraction.mapsProtocol(kind.protocol());
    }

    /** The counts by the kinds' texts, in their order: how JSON and people read them. */
    public static Map<String, Long> texts(Map<UnmappedMessage, Long> unmapped) {
        Map<String, Long> texts = new LinkedHashMap<>();
        new TreeMap<>(unmapped).forEach((kind, n) -> texts.put(kind.text(), n));
        return texts;
    }

    /** At most {@value #MAX_LINES} lines, one per command, then one that counts the commands left out. */
    public static List<String> lines(Map<UnmappedMessage, Long> unmapped) {
        List<Group> groups = groups(unmapped);
        List<String> lines = new ArrayList<>();
        int shown = groups.size() <= MAX_LINES ? groups.size() : MAX_LINES - 1;
        for (int i = 0; i < shown; i++) {
            lines.add(groups.get(i).describe());
        }
        if (shown < groups.size()) {
            long rest = groups.subList(shown, groups.size()).stream().mapToLong(Group::messages).sum();
            lines.add((groups.size() - shown) + " more commands (" + rest + " messages)");
        }
        return lines;
    }

    /**
     * Why the models cannot judge this log, in one line naming it, when its unmapped messages show that the
     * abstraction does not fit it: most interface records are unmapped, or commands of a component it maps that it
     * has no rule for (another robot, or another version of its interface). The locations it does not know are named
     * too, but a new place alone is no misfit: it is behaviour the models never saw, which the forecast follows
     * ({@link #novelty}). Interface messages of components the abstraction knows nothing of (a camera) are only
     * reported.
     *
     * @param interfaceRecords the log's interface records, mapped or not
     * @param abstraction      the abstraction the log was read with
     * @param consequence      what follows from it ({@code no verdict}), said after the reasons
     */
    public static Optional<String> misfit(String log, long interfaceRecords, Map<UnmappedMessage, Long> unmapped,
                                          Abstraction abstraction, String consequence) {
        long notMapped = unmapped.values().stream().mapToLong(Long::longValue).sum();
        List<String> unseen = new ArrayList<>();
        TreeSet<String> places = new TreeSet<>();
        Map<String, String> protocols = new LinkedHashMap<>(); // by command
        unmapped.keySet().forEach(m -> protocols.putIfAbsent(command(m), m.protocol()));
        for (Group g : groups(unmapped)) {
            places.addAll(g.locations());
            if (g.noRule() && abstraction.mapsProtocol(protocols.get(g.command()))) {
                unseen.add(g.command());
            }
        }
        boolean most = notMapped * 2 > interfaceRecords;
        if (!most && unseen.isEmpty()) {
            return Optional.empty(); // a new place alone is novelty, which the forecast follows through
        }
        places.forEach(p -> unseen.add("location '" + p + "'"));
        List<String> why = new ArrayList<>();
        if (most) {
            long mapped = interfaceRecords - notMapped;
            why.add(String.format(Locale.ROOT, "the abstraction '%s' maps only %d of its %d interface records (%d%%)",
                    abstraction.name(), mapped, interfaceRecords, mapped * 100 / Math.max(1, interfaceRecords)));
        }
        if (!unseen.isEmpty()) {
            why.add("it names what the abstraction '" + abstraction.name() + "' never saw: "
                    + String.join(", ", unseen.subList(0, Math.min(4, unseen.size())))
                    + (unseen.size() > 4 ? ", ..." : ""));
        }
        return Optional.of(log + ": " + String.join(", and ", why) + "; the models do not fit this log: " + consequence
                + "; "
                + likelyFix(unmapped, abstraction).map(name -> "try --abstraction " + name + ", with models learned "
                + "with it (--models)").orElse("are these the models of this robot, and the right --abstraction?"));
    }

    /**
     * The built-in abstraction that would map most of these messages, if one would map more than half of them: what
     * to try instead. Each kind is tried as a message of its command (with the location it names).
     */
    public static Optional<String> likelyFix(Map<UnmappedMessage, Long> unmapped, Abstraction current) {
        long total = unmapped.values().stream().mapToLong(Long::longValue).sum();
        String best = null;
        long bestCovered = 0;
        for (String name : AbstractionFiles.BUILTIN_NAMES) {
            if (name.equals(current.name())) {
                continue;
            }
            Abstraction other = AbstractionFiles.builtin(name).orElseThrow();
            long covered = 0;
            for (Map.Entry<UnmappedMessage, Long> e : unmapped.entrySet()) {
                if (!(other.classify(example(e.getKey())) instanceof Classification.Unmapped)) {
                    covered += e.getValue();
                }
            }
            if (covered * 2 > total && covered > bestCovered) {
                best = name;
                bestCovered = covered;
            }
        }
        return Optional.ofNullable(best);
    }

    /** A command message of the kind's command, naming the location the kind names (if it does). */
    private static LogRecord example(UnmappedMessage kind) {
        String location = kind.location() == null ? "" : kind.location();
        return new LogRecord(0, 0, "DEBUG", RecordKind.COMMAND, "", "", kind.protocol(), kind.command(), location, "");
    }
}
