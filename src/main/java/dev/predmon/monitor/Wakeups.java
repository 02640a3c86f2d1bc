package dev.predmon.monitor;

import dev.predmon.parse.LogFollower;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;

/**
 * Which logs of a following {@link Fleet} to poll now: those the operating system says were written, created,
 * renamed or deleted ({@link DirectoryWatch}), and, every pause, those whose changes cannot be notified. A log is
 * polled rather than notified when its directory cannot be watched (on a network file system, missing, or past the
 * inotify limit), when its path is a symbolic link (the target's writes are announced in the target's directory),
 * and every log when there is no notification at all or polling is forced. A directory that exists but cannot be
 * watched is told once, with why, so that the cost of polling its logs has a cause ({@code watch} says it on stderr).
 *
 * <p>A log whose name was deleted or renamed away is an <i>orphan</i> until its name is back: a writer may still
 * hold the old file, whose writes are then announced under its new name (or its last one, once deleted), so every
 * change in its directory polls it, and the follower drains the old file. Once a new file is at the path, the
 * follower finishes the old one only after it has been quiet for a while, a moment no event marks: such a log is
 * also polled every {@link #REPLACING_NANOS} until the follower has moved to the new file, and after that for as long
 * as it reads on in the renamed file (until that file has been quiet for the release time).
 */
final class Wakeups implements AutoCloseable {

    /**
     * How often a log in the middle of a rename rotation is looked at: a quarter of the quiet time after which its
     * follower finishes the renamed file, so the new file is taken at most that much later.
     */
    static final long REPLACING_NANOS = TimeUnit.MILLISECONDS.toNanos(LogFollower.QUIET_MILLIS) / 4;
    /**
     * The least time between two wakeups by notification: writes announced meanwhile are read together at the next
     * one. A write after a quiet spell is read at once; while logs are written faster than this, each wakeup reads
     * many, which is what keeps thousands of logs written at a robot's pace cheap. It adds at most this much to the
     * time from an append to its reading.
     */
    static final long GATHER_NANOS = TimeUnit.MILLISECONDS.toNanos(4);

    private final DirectoryWatch watch;
    private final long pauseNanos;
    private final Map<DirectoryWatch.Key, WatchedDirectory> byKey = new HashMap<>();
    private final Map<Path, WatchedDirectory> byDir = new HashMap<>();
    /** Per directory, whether its file system is one whose changes are not notified: asked once each. */
    private final Map<Path, Boolean> remote = new HashMap<>();
    /** Polled every pause. */
    private final Set<WatchedLog> polled = new LinkedHashSet<>();
    /** Polled at the next {@link #due}: just watched, so what they got before may not have been announced. */
    private final Set<WatchedLog> pending = new LinkedHashSet<>();
    /** Logs in the middle of a rename rotation, each with when to poll it next. */
    private final Map<WatchedLog, Long> replacing = new HashMap<>();
    private final List<DirectoryWatch.Key> invalid = new ArrayList<>();
    /** Told of each directory whose logs are polled because it cannot be watched, with why, once each. */
    private final BiConsumer<Path, String> unwatched;
    private final Set<Path> toldUnwatched = new HashSet<>();
    private long nextPass = System.nanoTime();
    /**
     * When changes were last taken. Which logs of the last {@link #due} were only announced as written is each log's
     * {@link WatchedLog#onlyWritten} (a set of them cost two lookups per log polled at robot pace).
     */
    private long lastTaken = System.nanoTime() - GATHER_NANOS;
    /** What the last {@link #due} gave: one set, cleared at each call, not one per wakeup. */
    private final Set<WatchedLog> due = new LinkedHashSet<>();
    private boolean rescan;
    private boolean sourcesWatched = true;

    /**
     * @param watch      the notification, or null to poll every log
     * @param pauseNanos the pause between two polls of a log that is polled
     * @param unwatched  told of each existing directory that cannot be watched (its logs are polled), with why in a
     *                   few words, once per directory; not of a directory that does not exist (yet)
     */
    Wakeups(DirectoryWatch watch, long pauseNanos, BiConsumer<Path, String> unwatched) {
        this.watch = watch;
        this.pauseNanos = pauseNanos;
        this.unwatched = unwatched;
    }

    /** Whether any log is notified rather than polled (only then is a safety poll worth it). */
    boolean notifying() {
        return !byKey.isEmpty();
    }

    /** Whether nothing is left to polling: no polled log, and every source directory watched. */
    boolean allWatched() {
        return polled.isEmpty() && sourcesWatched;
    }

    /** Follows {@code log} from now on: notified if its directory can be watched, else polled. */
    void add(WatchedLog log) {
        Path path = log.path().toAbsolutePath().normalize();
        WatchedDirectory w = Files.isSymbolicLink(path) || path.getParent() == null ? null : watched(path.getParent());
        if (w == null) {
            polled.add(log);
            return;
        }
        w.logs.computeIfAbsent(path.getFileName(), n -> new ArrayList<>(1)).add(log);
        pending.add(log);
    }

    /** Watches the directories in which a new file may be a new log, so that its creation asks for a rescan. */
    void watchSources(Collection<Path> dirs) {
        boolean all = watch != null;
        for (Path d : dirs) {
            WatchedDirectory w = watched(d.toAbsolutePath().normalize());
            if (w == null) {
                all = false;
            } else {
                w.source = true;
            }
        }
        sourcesWatched = all;
    }

    /** Whether a file was created in a source directory since the last rescan: new logs should be looked for. */
    boolean rescanWanted() {
        return rescan;
    }

    /** A rescan begins: it finds every file created before now. */
    void rescanning() {
        rescan = false;
    }

    /**
     * Looks again at what is not watched, or not as it was: a directory replaced or moved away under its watch
     * (the watch follows the old directory, so its logs are taken again from the path), and the directories of polled
     * logs, which may have appeared or fallen below the watch limit. Cheap: one look per directory.
     */
    void recheck() {
        for (WatchedDirectory w : List.copyOf(byKey.values())) {
            if (!Objects.equals(w.identity, DirectoryWatch.identity(w.dir))) {
                w.key.cancel();
                drop(w);
            }
        }
        if (watch == null || polled.isEmpty()) {
            return;
        }
        Set<Path> tried = new LinkedHashSet<>();
        for (WatchedLog log : List.copyOf(polled)) {
            Path path = log.path().toAbsolutePath().normalize();
            Path dir = path.getParent();
            if (dir != null && !Files.isSymbolicLink(path) && (byDir.containsKey(dir) || tried.add(dir))) {
                polled.remove(log);
                add(log); // back into polled if still not watchable
            }
        }
    }

    /**
     * After {@code log} was polled: while a replacement of its file waits for the old file to be quiet, nothing may
     * be written that would announce the moment to finish it, so the log is polled again every
     * {@link #REPLACING_NANOS} until its follower has moved on. So is a log whose renamed file is still read after the
     * turn: its writer's writes are announced under a name no log has, or in a directory not watched.
     */
    void polled(WatchedLog log) {
        if (log.watcher().replacing() || log.watcher().readingRenamed()) {
            replacing.putIfAbsent(log, System.nanoTime() + REPLACING_NANOS);
        }
    }

    /**
     * Waits up to {@code nanos} (less when a polled log's pause or a rotation's next look comes first) for changes,
     * and gives the logs to poll now, each once: a set the next call empties.
     */
    Set<WatchedLog> due(long nanos) throws InterruptedException {
        long now = System.nanoTime();
        long wait = pending.isEmpty() ? nanos : 0;
        if (!polled.isEmpty()) {
            wait = Math.min(wait, nextPass - now);
        }
        for (long at : replacing.values()) {
            wait = Math.min(wait, at - now);
        }
        Set<WatchedLog> out = due;
        for (WatchedLog log : out) {
            log.onlyWritten = false;
        }
        out.clear();
        if (watch == null) {
            TimeUnit.NANOSECONDS.sleep(Math.max(0, wait));
        } else {
            long gather = Math.min(wait, lastTaken + GATHER_NANOS - now);
            if (gather > 0) {
                TimeUnit.NANOSECONDS.sleep(gather); // what is written meanwhile is taken with what came already
                wait -= gather;
            }
            List<DirectoryWatch.Change> changes = watch.take(Math.max(0, wait), invalid);
            if (!changes.isEmpty()) {
                lastTaken = System.nanoTime();
            }
            for (DirectoryWatch.Change c : changes) {
                WatchedDirectory w = byKey.get(c.key());
                if (w != null) {
                    changed(w, c, out);
                }
            }
            for (DirectoryWatch.Key k : invalid) {
                WatchedDirectory w = byKey.get(k);
                if (w != null) {
                    full(drop(w), out); // a last look at each, now polled
                }
            }
            invalid.clear();
        }
        full(pending, out);
        pending.clear();
        long later = System.nanoTime();
        for (Iterator<Map.Entry<WatchedLog, Long>> i = replacing.entrySet().iterator(); i.hasNext(); ) {
            Map.Entry<WatchedLog, Long> next = i.next();
            if (later - next.getValue() >= 0) {
                full(List.of(next.getKey()), out); // polled() schedules it again if it still waits
                i.remove();
            }
        }
        if (!polled.isEmpty() && System.nanoTime() - nextPass >= 0) {
            full(polled, out);
            nextPass = System.nanoTime() + pauseNanos;
        }
        return out;
    }

    private void changed(WatchedDirectory w, DirectoryWatch.Change c, Set<WatchedLog> out) {
        if (c.kind() == DirectoryWatch.Kind.OVERFLOW) {
            w.logs.values().forEach(l -> full(l, out)); // events were lost: anything may have changed
            rescan |= w.source;
            return;
        }
        List<WatchedLog> named = w.logs.get(c.name());
        if (named == null) {
            rescan |= w.source && c.kind() == DirectoryWatch.Kind.CREATED;
        } else if (c.kind() == DirectoryWatch.Kind.MODIFIED) {
            for (WatchedLog log : named) {
                if (out.add(log)) {
                    log.onlyWritten = true;
                }
            }
        } else {
            full(named, out);
            if (c.kind() == DirectoryWatch.Kind.DELETED) {
                w.orphans.addAll(named);
            } else if (c.kind() == DirectoryWatch.Kind.CREATED) {
                named.forEach(w.orphans::remove);
                if (Files.isSymbolicLink(w.dir.resolve(c.name()))) {
                    w.logs.remove(c.name());
                    polled.addAll(named);
                }
            }
        }
        full(w.orphans, out);
    }

    /** {@code logs} are to be polled, each with a look at its path. */
    private void full(Collection<WatchedLog> logs, Set<WatchedLog> out) {
        if (logs.isEmpty()) {
            return;
        }
        for (WatchedLog log : logs) {
            out.add(log);
            log.onlyWritten = false;
        }
    }

    /**
     * Whether {@code log}, given by the last {@link #due}, was only announced as written: nothing was created, renamed
     * or deleted at its path, so its poll need not look at the path ({@link LogWatcher#pollWritten()}).
     */
    boolean onlyWritten(WatchedLog log) {
        return log.onlyWritten;
    }

    /** Stops watching {@code w}; its logs go back to {@link #add}, where they are watched again or polled. */
    private List<WatchedLog> drop(WatchedDirectory w) {
        byKey.remove(w.key);
        byDir.remove(w.dir);
        List<WatchedLog> logs = new ArrayList<>();
        w.logs.values().forEach(logs::addAll);
        logs.forEach(this::add);
        if (w.source) {
            sourcesWatched = false; // until the next rescan registers the source directories again
            rescan = true;
        }
        return logs;
    }

    /** The watch of {@code dir}, registered now if need be, or null when its changes must be polled for. */
    private WatchedDirectory watched(Path dir) {
        if (watch == null) {
            return null;
        }
        WatchedDirectory known = byDir.get(dir);
        if (known != null && known.key.isValid()) {
            return known;
        }
        if (Boolean.TRUE.equals(remote.computeIfAbsent(dir, DirectoryWatch::remote))) {
            tellUnwatched(dir, "network or FUSE file system, whose changes on other hosts are not notified");
            return null;
        }
        DirectoryWatch.Key key;
        try {
            key = watch.register(dir);
        } catch (IOException e) {
            if (Files.isDirectory(dir)) { // one that does not exist yet is watched once it does, without a word
                tellUnwatched(dir, DirectoryWatch.why(e));
            }
            return null;
        }
        // The same directory under another spelling gives the same key: its logs share one table.
        WatchedDirectory w = byKey.computeIfAbsent(key, k -> new WatchedDirectory(dir, k));
        byDir.put(dir, w);
        return w;
    }

    private void tellUnwatched(Path dir, String why) {
        if (toldUnwatched.add(dir)) {
            unwatched.accept(dir, why);
        }
    }

    /** Follows {@code log} no more: it is forgotten. */
    void remove(WatchedLog log) {
        polled.remove(log);
        pending.remove(log);
        replacing.remove(log);
        for (WatchedDirectory w : byKey.values()) {
            w.orphans.remove(log);
            w.logs.values().forEach(l -> l.remove(log));
            w.logs.values().removeIf(List::isEmpty);
        }
    }

    @Override
    public void close() throws IOException {
        if (watch != null) {
            watch.close();
        }
    }
}
