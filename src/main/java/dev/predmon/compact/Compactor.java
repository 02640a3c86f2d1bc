package dev.predmon.compact;

import dev.predmon.abstraction.AbstractEvent;
import dev.predmon.abstraction.Channel;
import dev.predmon.abstraction.Direction;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * Algorithm 5 (Compactor) of the thesis, streaming: pairs each reply with its command and keeps a pair only
 * when the query's answer changed.
 *
 * <p>The thesis's pseudo-code scans forward from every input for outputs that differ from the query's last
 * one; what it means (Section 4.2, Figure 4.8) is implemented here:
 * <ol>
 *   <li>A reply answers the pending command on its {@link Channel} (client and server, protocol, command; when
 *       both carry arguments they must be equal too). A reply with no pending command is an orphan: counted,
 *       ignored.</li>
 *   <li>RPC is synchronous per channel, so a new command on a channel whose command is still unanswered means
 *       the old one never will be: it is dropped (counted).</li>
 *   <li>A pair is kept when its output differs from the last output of the same query (input symbol); the
 *       first answer of a query is always kept. Every answered pair, kept or not, updates the last output.</li>
 *   <li>Replies can be printed after records that happened later on other channels (Figure 4.8a prints
 *       {@code o_goto_ki} at the end). Decisions are therefore made in the order of the <em>commands</em>: a
 *       queue holds commands in log order and pairs leave it only from the head, once the head is answered or
 *       dropped. The result is exactly that of the same log with every reply right after its command. A waiting
 *       head blocks the pairs behind it until its own channel's next command or {@link #endOfInput()}
 *       resolves it.</li>
 * </ol>
 *
 * <p>A processor in the BeepBeep sense: events are pushed, state is explicit, {@link #reset()} forgets it.
 * Not thread-safe.
 */
public final class Compactor {

    /** A command in the queue, with its reply once it arrives. */
    private static final class Entry {
        final AbstractEvent command;
        AbstractEvent reply;
        boolean dropped;

        Entry(AbstractEvent command) {
            this.command = command;
        }

        boolean resolved() {
            return reply != null || dropped;
        }
    }

    private final Consumer<IoPair> out;
    private final BandPath bandPath;
    private final Deque<Entry> queue = new ArrayDeque<>();
    private final Map<Channel, Entry> pending = new HashMap<>();
    private final Map<String, String> lastOutput = new HashMap<>();
    private long answered;
    private long kept;
    private long unansweredDropped;
    private long orphans;

    /** @param out receives the kept pairs, in the order of their commands in the log */
    public Compactor(Consumer<IoPair> out) {
        this(out, (from, to) -> List.of(to));
    }

    /**
     * @param out      receives the kept pairs, in the order of their commands in the log
     * @param bandPath the outputs a changed answer passes through (see {@link BandPath}); each becomes a pair
     */
    public Compactor(Consumer<IoPair> out, BandPath bandPath) {
        this.out = Objects.requireNonNull(out, "out");
        this.bandPath = Objects.requireNonNull(bandPath, "bandPath");
    }

    /** Takes the next abstract event in log order. */
    public void push(AbstractEvent event) {
        Objects.requireNonNull(event, "event");
        if (event.direction() == Direction.INPUT) {
            Entry entry = new Entry(event);
            Entry superseded = pending.put(event.channel(), entry);
            if (superseded != null) {
                superseded.dropped = true;
                unansweredDropped++;
            }
            queue.addLast(entry);
        } else {
            Entry entry = pending.get(event.channel());
            if (entry == null || !sameArguments(entry.command, event)) {
                orphans++;
                return;
            }
            // Answered: the channel keeps its map entry with no command (a null value), so that the channel's next
            // command replaces a value instead of allocating a new entry; a log has a handful of channels.
            pending.put(event.channel(), null);
            entry.reply = event;
        }
        drain();
    }

    private static boolean sameArguments(AbstractEvent command, AbstractEvent reply) {
        String a = command.record().arguments();
        String b = reply.record().arguments();
        return a.isEmpty() || b.isEmpty() || a.equals(b);
    }

    private void drain() {
        while (!queue.isEmpty() && queue.peekFirst().resolved()) {
            Entry e = queue.pollFirst();
            if (e.dropped) {
                continue;
            }
            answered++;
            String input = e.command.symbol();
            String output = e.reply.symbol();
            String last = lastOutput.put(input, output);
            if (!output.equals(last)) {
                for (String passed : bandPath.path(last, output)) {
                    kept++;
                    out.accept(new IoPair(input, passed, e.command.record(), e.reply.record()));
                }
            }
        }
    }

    /** The input is over: commands still waiting for a reply are dropped (and counted). */
    public void endOfInput() {
        for (Entry e : pending.values()) {
            if (e != null) {
                e.dropped = true;
                unansweredDropped++;
            }
        }
        pending.clear();
        drain();
    }

    /** Forgets everything (the log was truncated or replaced). */
    public void reset() {
        queue.clear();
        pending.clear();
        lastOutput.clear();
        answered = 0;
        kept = 0;
        unansweredDropped = 0;
        orphans = 0;
    }

    /** Counts so far. */
    public CompactorStats stats() {
        return new CompactorStats(answered, kept, unansweredDropped, orphans);
    }

    /** Commands waiting in the queue (answered or not) behind an unanswered head; for monitoring memory. */
    public int queued() {
        return queue.size();
    }
}
