package dev.predmon.bench;

import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.LogSources;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

/**
 * {@link Fleet#follow} over a directory of logs on its own thread, as {@code watch --log DIR} runs it, until closed:
 * closing interrupts the thread, which is how watching ends, and fails if following failed.
 */
final class Following implements AutoCloseable {

    private final Thread thread;
    private final AtomicReference<Throwable> failed = new AtomicReference<>();

    /**
     * @param pauseNanos the pause between two polls of a log that is polled
     * @param polling    poll every log ({@code watch --polling}) instead of waiting for notifications
     */
    Following(Fleet fleet, Path logs, long pauseNanos, boolean polling) {
        LogSources sources = new LogSources(List.of(logs));
        thread = new Thread(() -> {
            try {
                fleet.follow(sources, pauseNanos, polling);
            } catch (Throwable t) {
                failed.set(t);
            }
        }, "predmon-bench-follow");
        thread.start();
    }

    /** The following thread, whose own CPU time the bench reads. */
    Thread thread() {
        return thread;
    }

    @Override
    public void close() throws Exception {
        thread.interrupt();
        thread.join();
        if (failed.get() != null) {
            throw new IllegalStateException("following failed", failed.get());
        }
    }
}
