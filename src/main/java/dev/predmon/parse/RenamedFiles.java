package dev.predmon.parse;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.DirectoryIteratorException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;

/**
 * The files a {@link LogFollower} turned away from at a rename rotation, still read: a logger that paused after the
 * rotation may go on writing to the renamed file, since nothing told it to reopen its log. Each is read with its own
 * partial line and sink for as long as it grows, and let go (its last line delivered, then
 * {@link LineSink#ended()}) once it has not grown for the release time, once it is truncated, or once it is deleted.
 *
 * <p>A renamed file is looked for at the turn among the files of the log's directory whose names begin as the log's
 * does ({@code live.log.1}, {@code live-20260101.log}), so that its deletion is noticed, also after a later rotation
 * renamed it again. One not found there (moved to another directory) is let go only once quiet. At most {@value #MAX}
 * are held; beyond, the one turned away from first is let go.
 */
final class RenamedFiles {

    /** Renamed files read at most at a time. */
    static final int MAX = 4;

    /** A renamed file and where it was last found; {@code at} is null where it could not be found. */
    private static final class Held {
        final FileReading reading;
        Path at;

        Held(FileReading reading, Path at) {
            this.reading = reading;
            this.at = at;
        }
    }

    private final Path log;
    private final ArrayDeque<Held> held = new ArrayDeque<>();

    /** @param log the followed path, whose directory holds the renamed files */
    RenamedFiles(Path log) {
        this.log = log;
    }

    boolean isEmpty() {
        return held.isEmpty();
    }

    /** Files held open. */
    int open() {
        return held.size();
    }

    /** Reads on in {@code reading}, the file just turned away from; the oldest held is let go if too many are. */
    void add(FileReading reading) throws IOException {
        if (held.size() >= MAX) {
            letGo(held.poll());
        }
        held.add(new Held(reading, locate(log, reading.identity)));
    }

    /**
     * Reads what was appended to each renamed file, oldest first, and lets go those that are done with.
     *
     * @return whether anything was read
     */
    boolean poll(long now, long releaseNanos) throws IOException {
        boolean progress = false;
        for (Iterator<Held> i = held.iterator(); i.hasNext(); ) {
            Held h = i.next();
            FileReading r = h.reading;
            boolean truncated = r.channel.size() < r.position;
            if (!truncated) {
                progress |= r.read(now);
            }
            if (truncated || gone(h) || now - r.lastGrowth >= releaseNanos) {
                i.remove();
                letGo(h);
            }
        }
        return progress;
    }

    /** Reads what each renamed file holds, then lets every one go (to spare descriptors, or at the end of a drain). */
    void letGoAll(long now) throws IOException {
        IOException first = null;
        while (!held.isEmpty()) {
            Held h = held.poll();
            try {
                if (h.reading.channel.size() >= h.reading.position) {
                    h.reading.read(now);
                }
            } catch (IOException e) {
                first = first == null ? e : first;
            }
            letGo(h);
        }
        if (first != null) {
            throw first;
        }
    }

    /** The channels held, for closing them all. */
    List<FileChannel> channels() {
        List<FileChannel> out = new ArrayList<>();
        held.forEach(h -> out.add(h.reading.channel));
        held.clear();
        return out;
    }

    private static void letGo(Held h) throws IOException {
        h.reading.end();
        h.reading.close();
    }

    /** Whether a renamed file that was found is no longer anywhere it can be found: deleted. */
    private boolean gone(Held h) throws IOException {
        Path at = h.at;
        if (at == null) {
            return false;
        }
        FileAt now = FileAt.look(at);
        if (now != null && now.identity().equals(h.reading.identity)) {
            return false;
        }
        h.at = locate(log, h.reading.identity); // renamed again by a later rotation, or deleted
        return h.at == null;
    }

    /**
     * Where the file of {@code identity} is among the files beside {@code log} whose names begin as its does (up to its
     * first dot), other than {@code log} itself; null if none is.
     */
    static Path locate(Path log, Object identity) {
        Path dir = log.toAbsolutePath().getParent();
        String name = log.getFileName().toString();
        int dot = name.indexOf('.', 1);
        String stem = dot < 0 ? name : name.substring(0, dot);
        if (dir == null) {
            return null;
        }
        DirectoryStream.Filter<Path> filter = p -> {
            String n = p.getFileName().toString();
            return n.startsWith(stem) && !n.equals(name);
        };
        try (DirectoryStream<Path> candidates = Files.newDirectoryStream(dir, filter)) {
            for (Path p : candidates) {
                FileAt at = FileAt.look(p);
                if (at != null && at.regular() && at.identity().equals(identity)) {
                    return p;
                }
            }
        } catch (IOException | DirectoryIteratorException e) {
            return null; // the directory cannot be listed: the file is let go once quiet
        }
        return null;
    }
}
