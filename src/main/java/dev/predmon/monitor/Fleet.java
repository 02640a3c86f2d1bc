package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;

import java.io.IOException;
import java.nio.channels.ClosedByInterruptException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Several logs watched in one process, by one thread: each log has its own {@link LogWatcher} and
 * {@link PredictiveMonitor} ({@link WatchedLog}), and one loop polls them in turn. One log is a fleet of one, so
 * {@code watch} has a single code path.
 *
 * <p>Each pass polls every log once; a poll reads everything appended since the last one, so a pass is followed
 * by the pause whether or not it read anything: with many robots writing, some log almost always has something
 * new, and re-polling at once would spin. A record appended just after its log was polled waits at most one pause
 * plus one pass (see {@code bench --only fleet} for what that costs with 100 logs).
 */
public final class Fleet implements AutoCloseable {

    /** Rescans of directories and globs for new logs, at most this often. */
    static final long RESCAN_NANOS = 1_000_000_000L;

    /** What a fleet reports, always from the thread that polls it. */
    public interface Listener {

        /** A log is watched from now on (it may not exist yet). */
        default void added(WatchedLog log) {
        }

        /** An event of {@code log}'s monitor, in its log order. */
        void event(WatchedLog log, MonitorEvent event);

        /** A record of {@code log}, just after its monitor took it (see {@link LogWatcher#withRecords}). */
        default void record(WatchedLog log, LogRecord record) {
        }

        /** Something in {@code log} the parser could not take as a record. */
        default void problem(WatchedLog log, ParseProblem problem) {
        }

        /** A poll found {@code log} grown (or truncated or replaced). */
        default void grew(WatchedLog log) {
        }

        /** Looking for new logs under a directory or glob failed; the fleet goes on and looks again later. */
        default void rescanFailed(IOException e) {
        }
    }

    /** How each log's monitor matches: the same for every log. */
    record Settings(ModelSet models, Abstraction abstraction, int threshold, int confirm, WarningRule rule) {
    }

    private final Settings settings;
    private final Listener listener;
    private final Map<Path, WatchedLog> logs = new LinkedHashMap<>();

    /**
     * @param threshold discrepancies a model may accumulate and still match (0: exact matching)
     * @param confirm   pairs a faulty model must match after the last nominal one is eliminated before a warning
     */
    public Fleet(ModelSet models, Abstraction abstraction, int threshold, int confirm, Listener listener) {
        this(models, abstraction, threshold, confirm, PredictiveMonitor.defaultRule(models), listener);
    }

    /** A fleet whose monitors warn by {@code rule}. */
    public Fleet(ModelSet models, Abstraction abstraction, int threshold, int confirm, WarningRule rule,
                 Listener listener) {
        this.settings = new Settings(models, abstraction, threshold, confirm, rule);
        this.listener = listener;
    }

    /** Watches {@code log} from now on, unless it is watched already (under any spelling of its path). */
    public WatchedLog add(Path log) {
        Path key = log.toAbsolutePath().normalize();
        WatchedLog known = logs.get(key);
        if (known != null) {
            return known;
        }
        WatchedLog added = new WatchedLog(log, settings, listener);
        logs.put(key, added);
        listener.added(added);
        return added;
    }

    /** The logs watched, in the order they were added. */
    public List<WatchedLog> logs() {
        return List.copyOf(logs.values());
    }

    /** One pass: polls every log once; whether any had something new. */
    public boolean poll() throws IOException {
        boolean any = false;
        for (WatchedLog log : logs.values()) {
            if (log.watcher().poll()) {
                any = true;
                listener.grew(log);
            }
        }
        return any;
    }

    /** Reads every log to its end and completes its trace ({@code --no-follow}). */
    public void drain() throws IOException {
        for (WatchedLog log : logs.values()) {
            log.watcher().drain();
        }
    }

    /**
     * Follows every log until the thread is interrupted, which is how watching is meant to end: an interrupt while
     * sleeping or reading is a stop, not an error, and leaves the interrupt status set. Directories and globs among
     * {@code sources} are looked at again about once a second for new logs.
     *
     * @param pauseMillis the pause after each pass ({@code --poll-ms})
     */
    public void follow(LogSources sources, long pauseMillis) throws IOException {
        long nextScan = System.nanoTime() + RESCAN_NANOS;
        boolean growing = sources.growing();
        try {
            while (!Thread.currentThread().isInterrupted()) {
                if (growing && System.nanoTime() - nextScan >= 0) {
                    rescan(sources);
                    nextScan = System.nanoTime() + RESCAN_NANOS;
                }
                poll();
                Thread.sleep(pauseMillis);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ClosedByInterruptException e) {
            // interrupted while reading (FileChannel reads are interruptible); the interrupt status stays set
        }
    }

    private void rescan(LogSources sources) throws ClosedByInterruptException {
        try {
            sources.find().forEach(this::add);
        } catch (ClosedByInterruptException stop) {
            throw stop;
        } catch (IOException e) {
            // A directory that went away or cannot be read while it was walked: the logs watched so far go on.
            listener.rescanFailed(e);
        }
    }

    /** Whether any log's monitor has raised a warning. */
    public boolean warned() {
        return logs.values().stream().anyMatch(l -> l.monitor().warning().isPresent());
    }

    @Override
    public void close() throws IOException {
        IOException first = null;
        for (WatchedLog log : new ArrayList<>(logs.values())) {
            try {
                log.watcher().close();
            } catch (IOException e) {
                if (first == null) {
                    first = e;
                } else {
                    first.addSuppressed(e);
                }
            }
        }
        if (first != null) {
            throw first;
        }
    }
}
