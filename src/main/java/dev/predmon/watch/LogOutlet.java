package dev.predmon.watch;

import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.live.Tile;
import dev.predmon.pipeline.UnmappedMessages;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/** Where one log's events go in a {@link WatchSession}, and what is known of its evidence so far. */
final class LogOutlet {

    final EventPrinter printer;
    /** Its tile on the live view, or null without one. */
    final Tile tile;
    final ProblemLines problems = new ProblemLines();
    /** Something recognisable arrived, or the notice that nothing did was given. */
    boolean settled;
    /** When the log's first line was read ({@link System#nanoTime()}), 0 before. */
    long firstLineNanos;
    /** The runs that began where the log was truncated or replaced, with which of the two. */
    final Map<Integer, String> restarts = new HashMap<>();
    /** Whether the line that the file holds only YARP's start-up lines so far was given. */
    boolean toldPreamble;
    /** Whether the line that the file is followed was given. */
    boolean announced;
    /** The commands of unmapped messages said at their first sighting. */
    private final Set<String> commandsSeen = new HashSet<>();

    LogOutlet(EventPrinter printer, Tile tile) {
        this.printer = printer;
        this.tile = tile;
    }

    /**
     * Whether an unmapped {@code message} is the first of its command, to be said: of at most
     * {@value UnmappedMessages#MAX_LINES} commands, and one more to say that there are more.
     */
    boolean firstOfItsCommand(UnmappedMessage message) {
        return commandsSeen.size() <= UnmappedMessages.MAX_LINES
                && commandsSeen.add(message.name());
    }

    /** How many commands of unmapped messages were seen (at most one past {@value UnmappedMessages#MAX_LINES}). */
    int commandsSeen() {
        return commandsSeen.size();
    }
}
