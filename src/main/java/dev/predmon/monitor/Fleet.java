package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.LogFormat;

import java.io.IOException;
import java.nio.channels.ClosedByInterruptException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Several logs watched in one process, by one thread: each log has its own {@link LogWatcher} and
 * {@link PredictiveMonitor} ({@link WatchedLog}). One log is a fleet of one, so {@code watch} has a single code path.
 *
 * <p>While following, the thread sleeps until the operating system says that a file in a log's directory changed
 * ({@link Wakeups}, {@link DirectoryWatch}), then polls just the logs concerned: a thousand idle logs cost almost
 * nothing, and an append is read within a millisecond or so. Logs whose changes cannot be notified (a network file
 * system, a directory that cannot be watched, or {@code --polling}) are polled after every pause instead: a record
 * appended just after its log was polled waits at most one pause plus one pass. Every {@link #SAFETY_NANOS} every
 * log is polled anyway, a slice at a time, as a backstop for what no notification covers: a file written through a
 * memory map or a hard link in another directory, a directory replaced under its watch before {@link Wakeups#recheck}
 * sees it. Directories and globs are looked at again for new logs on a thread of their own ({@link Rescan}).
 */
public final class Fleet implements AutoCloseable {

    /** Rescans of directories and globs for new logs when some are not watched, and retries of watches. */
    static final long RESCAN_NANOS = 1_000_000_000L;
    /** Every log polled, notified or not, and the rescan when everything is watched: the backstop. */
    static final long SAFETY_NANOS = 2_000_000_000L;
    /** How often the listener hears a {@link FleetListener#pulse()}. */
    static final long PULSE_NANOS = 500_000_000L;
    /** A file created in a watched directory asks for a rescan, which waits this long after the last one. */
    static final long RESCAN_SOON_NANOS = 50_000_000L;
    /** The backstop polls the logs in this many slices, one every {@link #SAFETY_NANOS} / this. */
    static final int SAFETY_SLICES = 20;
    /** How often the following thread looks whether a rescan on its own thread is done. */
    static final long RESCAN_LOOK_NANOS = 10_000_000L;

    /**
     * How each log's monitor matches: the same for every log; {@code release}: how long a file gone from its log's
     * path is held open after it last grew.
     */
    record Settings(ModelSet models, Abstraction abstraction, int tolerance, int confirm, WarningRule rule,
                    Duration release) {
    }

    private Settings settings;
    private final FleetListener listener;
    private final Map<Path, WatchedLog> logs = new LinkedHashMap<>();
    private OpenFiles openFiles = new OpenFiles(OpenFiles.defaultBudget());
    /** While following: told of each log added. */
    private Wakeups wakeups;
    /** Where the backstop's next slice begins. */
    private final Slices<WatchedLog> backstop = new Slices<>(SAFETY_SLICES);
    private DeletedLogs deleted = new DeletedLogs(DeletedLogs.KEPT, DeletedLogs.EVERY);

    /**
     * @param tolerance discrepancies a model may accumulate and still match (0: exact matching)
     * @param confirm   pairs a faulty model must match after the last nominal one is eliminated before a warning
     */
    public Fleet(ModelSet models, Abstraction abstraction, int tolerance, int confirm, FleetListener listener) {
        this(models, abstraction, tolerance, confirm, PredictiveMonitor.defaultRule(models), listener);
    }

    /** A fleet whose monitors warn by {@code rule}. */
    public Fleet(ModelSet models, Abstraction abstraction, int tolerance, int confirm, WarningRule rule,
                 FleetListener listener) {
        this.settings = new Settings(models, abstraction, tolerance, confirm, rule, LogWatcher.DEFAULT_RELEASE);
        this.listener = listener;
    }

    /**
     * For tests, before any log is added: how long a file gone from the path is held open, and how many files the
     * fleet may hold open.
     */
    void limits(Duration release, int budget) {
        settings = new Settings(settings.models(), settings.abstraction(), settings.tolerance(), settings.confirm(),
                settings.rule(), release);
        openFiles = new OpenFiles(budget);
    }

    /** For tests: a deleted log is forgotten {@code kept} after it is found gone, looked for every {@code every}. */
    void forgetDeleted(Duration kept, Duration every) {
        deleted = new DeletedLogs(kept, every);
    }

    /** How many files the fleet's logs hold open now. */
    int openFiles() {
        return openFiles.open();
    }

    /** Watches {@code log} from now on, unless it is watched already (under any spelling of its path). */
    public WatchedLog add(Path log) {
        return add(log, log.toString(), null);
    }

    /**
     * Watches a log read in {@code format} (the abstraction's when null) under {@code name}, unless {@code log} is
     * watched already: a source that is no file (a live robot) names itself, its path only tells it apart.
     */
    public WatchedLog add(Path log, String name, LogFormat format) {
        Path key = log.toAbsolutePath().normalize();
        WatchedLog known = logs.get(key);
        if (known != null) {
            return known;
        }
        WatchedLog added = new WatchedLog(log, name, format, settings, listener);
        logs.put(key, added);
        listener.added(added);
        if (wakeups != null) {
            wakeups.add(added);
        }
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
            any |= poll(log, false);
        }
        return any;
    }

    /**
     * Polls one log. A log that cannot be read (what is at its path is no file, a read fails) is told once and
     * watched on; it never stops the others. When the fleet holds more files than it may, the logs idle longest
     * are closed, to be reopened when they change.
     */
    private boolean poll(WatchedLog log, boolean onlyWritten) throws ClosedByInterruptException {
        boolean grew = false;
        String trouble = null;
        try {
            grew = onlyWritten ? log.watcher().pollWritten() : log.watcher().poll();
        } catch (ClosedByInterruptException stop) {
            throw stop;
        } catch (IOException e) {
            if (OpenFiles.exhausted(e)) {
                openFiles.exhausted();
                trouble = relieve(log) ? null : log.name() + ": cannot be opened: too many open files";
            } else {
                trouble = log.name() + ": cannot be read (" + DirectoryWatch.why(e) + "); still watching it";
            }
        }
        if (trouble == null) {
            trouble = log.watcher().obstacle().map(o -> log.name() + ": " + o + "; watching for a log file there")
                    .orElse(null);
        }
        if (trouble != null && !trouble.equals(log.told)) {
            listener.notice(trouble);
        }
        log.told = trouble;
        log.watcher().takeNotice().ifPresent(n -> listener.notice(log.name() + ": " + n));
        openFiles.polled(log, grew);
        if (openFiles.over()) {
            relieve(log);
        }
        if (grew) {
            listener.grew(log);
        }
        return grew;
    }

    /** Closes idle logs' files, saying so the first time; whether any could be closed. */
    private boolean relieve(WatchedLog keep) {
        int before = openFiles.open();
        try {
            if (openFiles.relieve(keep)) {
                listener.notice(logs.size() + " logs need more open files than this process may hold ("
                        + openFiles.budget() + "): the files of idle logs are closed and reopened when they change");
            }
        } catch (IOException e) {
            listener.notice("closing idle logs: " + DirectoryWatch.why(e));
        }
        return openFiles.open() < before;
    }

    /** Reads every log to its end and completes its trace ({@code --no-follow}); each file is closed once read. */
    public void drain() throws IOException {
        for (WatchedLog log : logs.values()) {
            log.watcher().drain();
            log.watcher().release();
        }
    }

    /**
     * Follows every log until the thread is interrupted, which is how watching is meant to end: an interrupt while
     * waiting or reading is a stop, not an error, and leaves the interrupt status set. Directories and globs among
     * {@code sources} are looked at again for new logs when a file is created in them, and every
     * {@link #SAFETY_NANOS} (every {@link #RESCAN_NANOS} while one of their directories cannot be watched).
     *
     * @param pauseNanos the pause between two polls of a log whose changes are not notified ({@code --poll-ms})
     * @param polling    poll every log after each pause, without the operating system's notification
     */
    public void follow(LogSources sources, long pauseNanos, boolean polling) throws IOException {
        follow(sources, pauseNanos, polling, SAFETY_NANOS);
    }

    /**
     * As above, with the backstop's period: tests set it beyond their length, so that only the notification or the
     * polling under test can wake the fleet.
     */
    void follow(LogSources sources, long pauseNanos, boolean polling, long safetyNanos) throws IOException {
        boolean growing = sources.growing();
        DirectoryWatch watch = polling ? null
                : DirectoryWatch.open(why -> listener.unnotified(null, why, pauseNanos));
        try (Wakeups w = new Wakeups(watch, pauseNanos, (dir, why) -> listener.unnotified(dir, why, pauseNanos));
             Rescan rescan = new Rescan(sources)) {
            wakeups = w;
            logs.values().forEach(w::add);
            poll(); // the logs as they are as following begins: their history
            listener.caughtUp();
            if (growing) {
                found(rescan, true); // also watches the directories in which new logs may appear
            }
            long now = System.nanoTime();
            long lastScan = now;
            long nextCheck = now + RESCAN_NANOS;
            long nextSlice = now + safetyNanos / SAFETY_SLICES;
            long nextPulse = now + PULSE_NANOS;
            long nextForget = now + deleted.everyNanos();
            long pause = listener.beat();
            long nextBeat = now + pause;
            while (!Thread.currentThread().isInterrupted()) {
                now = System.nanoTime();
                if (now - nextPulse >= 0) {
                    listener.pulse();
                    nextPulse = now + PULSE_NANOS;
                }
                if (pause != Long.MAX_VALUE && now - nextBeat >= 0) {
                    pause = listener.beat();
                    nextBeat = now + pause;
                }
                found(rescan, false);
                long scanPeriod = w.allWatched() ? safetyNanos : RESCAN_NANOS;
                if (growing && !rescan.running() && (now - lastScan >= scanPeriod
                        || (w.rescanWanted() && now - lastScan >= RESCAN_SOON_NANOS))) {
                    w.rescanning();
                    rescan.start();
                    lastScan = now;
                }
                if (growing && now - nextForget >= 0) {
                    forget(sources, w);
                    nextForget = now + deleted.everyNanos();
                }
                if (now - nextCheck >= 0) {
                    w.recheck();
                    nextCheck = now + (w.allWatched() ? safetyNanos : RESCAN_NANOS);
                }
                if (now - nextSlice >= 0) {
                    if (w.notifying()) {
                        for (WatchedLog log : backstop.next(logs.values())) {
                            poll(log, false);
                        }
                    }
                    nextSlice = now + safetyNanos / SAFETY_SLICES;
                }
                long until = Math.min(Math.min(nextCheck, nextSlice), nextPulse);
                if (pause != Long.MAX_VALUE && nextBeat - until < 0) {
                    until = nextBeat;
                }
                if (growing) {
                    until = Math.min(Math.min(until, nextForget),
                            lastScan + (w.rescanWanted() ? RESCAN_SOON_NANOS : scanPeriod));
                }
                if (rescan.running()) {
                    until = Math.min(until, now + RESCAN_LOOK_NANOS);
                }
                for (WatchedLog log : w.due(until - System.nanoTime())) {
                    poll(log, w.onlyWritten(log));
                    w.polled(log);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ClosedByInterruptException e) {
            // interrupted while reading (FileChannel reads are interruptible); the interrupt status stays set
        } finally {
            wakeups = null;
        }
    }

    /** Adds the logs a look found (made now, or on the rescan's thread if done) and watches their directories. */
    private void found(Rescan rescan, boolean now) throws ClosedByInterruptException, InterruptedException {
        try {
            Rescan.Found found = now ? rescan.now() : rescan.take();
            if (found != null) {
                found.files().forEach(this::add);
                wakeups.watchSources(found.directories());
            }
        } catch (ClosedByInterruptException stop) {
            throw stop;
        } catch (IOException e) {
            // A directory that went away or cannot be read while it was walked: the logs watched so far go on.
            listener.rescanFailed(e);
        }
    }

    /** Forgets the logs found under a directory or glob that were deleted long enough ago ({@link DeletedLogs}). */
    private void forget(LogSources sources, Wakeups w) {
        for (WatchedLog log : deleted.due(logs.values(), l -> sources.named(l.path()), System.nanoTime())) {
            logs.remove(log.path().toAbsolutePath().normalize());
            sources.forget(log.path()); // found again by the next look if it is back
            w.remove(log);
            backstop.forget(log);
            openFiles.closed(log);
            try {
                log.watcher().close();
            } catch (IOException e) {
                listener.notice(log.name() + ": closing: " + DirectoryWatch.why(e));
            }
            listener.forgotten(log);
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
                openFiles.closed(log);
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
