package dev.predmon.monitor;

import java.io.IOException;
import java.nio.channels.ClosedByInterruptException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * The looks at a fleet's directories and globs for new logs, on a thread of their own: listing a directory of
 * 10,000 logs and telling each file's identity takes tens of milliseconds, more on a busy machine, and the following
 * thread reads appends meanwhile. The following thread starts a look ({@link #start}) and takes what it found
 * ({@link #take}) at its next wakeup after it is done; only it adds logs and watches directories.
 */
final class Rescan implements AutoCloseable {

    /**
     * What one look found: the files the names stand for that the look before did not list (every one at the first
     * look), and the directories new logs may appear in.
     */
    record Found(List<Path> files, List<Path> directories) {
    }

    /** One look. */
    interface Look {
        Found look() throws IOException;
    }

    private final Look look;
    private ExecutorService thread;
    private Future<Found> running;

    /** Looks at what {@code sources} stand for: a look costs a listing, and a stat only for what is new. */
    Rescan(LogSources sources) {
        this(() -> new Found(sources.findNew(), sources.directories()));
    }

    Rescan(Look look) {
        this.look = look;
    }

    /** Looks now, on the calling thread (as following begins, so that every log there is followed from the start). */
    Found now() throws IOException {
        return look.look();
    }

    /** Starts a look unless one is under way. */
    void start() {
        if (running != null) {
            return;
        }
        if (thread == null) {
            thread = Executors.newSingleThreadExecutor(r -> {
                Thread t = new Thread(r, "predmon-rescan");
                t.setDaemon(true);
                return t;
            });
        }
        running = thread.submit(this::now);
    }

    /** Whether a look is under way. */
    boolean running() {
        return running != null;
    }

    /**
     * What the look found once it is done, else null.
     *
     * @throws IOException what the look failed with (a directory that went away while it was listed)
     */
    Found take() throws IOException, InterruptedException {
        if (running == null || !running.isDone()) {
            return null;
        }
        Future<Found> done = running;
        running = null;
        try {
            return done.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof IOException io && !(io instanceof ClosedByInterruptException)) {
                throw io;
            }
            throw new IOException(e.getCause());
        }
    }

    @Override
    public void close() {
        if (thread != null) {
            thread.shutdownNow();
        }
    }
}
