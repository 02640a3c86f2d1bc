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
    /** The file turned away from at the last replacement, kept open a while to notice a writer that went on in it. */
    private FileChannel retired;
    private long retiredSize;
    private long retiredAt;

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

    /** The file read until now is done: it is kept open (the one kept before is closed) to see whether it grows. */
    void retire(FileChannel done, long now) throws IOException {
        closeRetired();
        retired = done;
        retiredSize = done.size();
        retiredAt = now;
    }

    /**
     * How many bytes were written to the retired file since it was retired; once it grew, or once it was kept for
     * {@code keepNanos}, it is closed.
     */
    long retiredGrowth(long now, long keepNanos) throws IOException {
        if (retired == null) {
            return 0;
        }
        long grown = retired.size() - retiredSize;
        if (grown > 0 || now - retiredAt >= keepNanos) {
            closeRetired();
        }
        return Math.max(0, grown);
    }

    /** Files held open: those waiting and the retired one. */
    int open() {
        return waiting.size() + (retired == null ? 0 : 1);
    }

    void closeRetired() throws IOException {
        if (retired != null) {
            FileChannel r = retired;
            retired = null;
            r.close();
        }
    }

    /** The files held, the retired one included, for closing them. */
    List<FileChannel> channels() {
        List<FileChannel> all = new ArrayList<>(waiting.stream().map(Waiting::channel).toList());
        if (retired != null) {
            all.add(retired);
        }
        return all;
    }

    void clear() {
        waiting.clear();
        retired = null;
    }
}
