package dev.predmon.monitor;

import java.nio.file.Files;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;

/**
 * The logs of a {@link Fleet} that were deleted long enough ago to be forgotten, so that a fleet whose logs come and
 * go does not keep a monitor (its models' states, its runs, its tile and series) for every log it ever watched. A log
 * is gone when nothing is at its path and its follower holds none of its files any more: a deleted file still
 * written is read as long as it grows, and let go once it has not grown for the release time. Only logs found under
 * a directory or glob are forgotten; a log named on the command line is waited for.
 */
public final class DeletedLogs {

    /** How long a deleted log is kept, its tile saying so, before it is forgotten. */
    public static final Duration KEPT = Duration.ofMinutes(10);
    /** How often the logs are looked at: a look is a {@code stat} of each log that holds no file open. */
    static final Duration EVERY = Duration.ofMinutes(1);

    private final long keptNanos;
    private final long everyNanos;
    /** When each log was first found gone ({@link System#nanoTime()}). */
    private final Map<WatchedLog, Long> goneSince = new HashMap<>();

    DeletedLogs(Duration kept, Duration every) {
        this.keptNanos = kept.toNanos();
        this.everyNanos = every.toNanos();
    }

    long everyNanos() {
        return everyNanos;
    }

    /**
     * The logs among {@code logs} gone for at least the time kept at {@code now}, to be forgotten; {@code named} tells
     * the logs named on the command line, which never are.
     */
    List<WatchedLog> due(Collection<WatchedLog> logs, Predicate<WatchedLog> named, long now) {
        List<WatchedLog> out = new ArrayList<>();
        for (WatchedLog log : logs) {
            if (!log.file() || named.test(log) || log.watcher().openFiles() > 0 || Files.exists(log.path())) {
                goneSince.remove(log);
                continue;
            }
            long since = goneSince.computeIfAbsent(log, l -> now);
            if (now - since >= keptNanos) {
                goneSince.remove(log);
                out.add(log);
            }
        }
        return out;
    }
}
