package dev.predmon.parse;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * The files a {@link LogFollower} found at its path after the one it reads, oldest first, each held open until its
 * turn: a log rotated again before the renamed one was finished. At most {@value #MAX} are held; beyond, the oldest
 * is taken at once.
 */
final class Replacements {

    /** Replacements held open at most while the file read is still written. */
    static final int MAX = 8;

    /** A replacement held open until the file before it is finished. */
    record Waiting(FileChannel channel, Object identity) {
    }

    private final ArrayDeque<Waiting> waiting = new ArrayDeque<>();

    boolean isEmpty() {
        return waiting.isEmpty();
    }

    int size() {
        return waiting.size();
    }

    /** Whether no more may be held: the oldest must be taken now. */
    boolean full() {
        return waiting.size() >= MAX;
    }

    /** Whether the file of this identity is held already. */
    boolean holds(Object identity) {
        return waiting.stream().anyMatch(w -> w.identity().equals(identity));
    }

    void add(FileChannel channel, Object identity) {
        waiting.add(new Waiting(channel, identity));
    }

    /** Whether a file held holds something. */
    boolean anyHolds() throws IOException {
        for (Waiting w : waiting) {
            if (w.channel().size() > 0) {
                return true;
            }
        }
        return false;
    }

    /**
     * The next file to read, taken off the queue. One that is still empty while a later one holds something is closed
     * and passed over: it was rotated away before its turn (twice before the logger reopened, or deleted).
     */
    Waiting next() throws IOException {
        Waiting next = waiting.poll();
        while (next.channel().size() == 0 && !waiting.isEmpty() && anyHolds()) {
            next.channel().close();
            next = waiting.poll();
        }
        return next;
    }

    /** Files held open. */
    int open() {
        return waiting.size();
    }

    /** The files held, for closing them. */
    List<FileChannel> channels() {
        return new ArrayList<>(waiting.stream().map(Waiting::channel).toList());
    }

    void clear() {
        waiting.clear();
    }
}
