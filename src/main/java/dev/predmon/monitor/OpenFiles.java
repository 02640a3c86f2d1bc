package dev.predmon.monitor;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.OperatingSystemMXBean;
import java.nio.file.FileSystemException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Set;

/**
 * The files a {@link Fleet}'s logs hold open, kept within what the process may open ({@code ulimit -n}): a fleet
 * larger than that keeps following every log by closing the files of the logs that were idle longest, which their
 * next change reopens ({@link LogWatcher#release()}). The budget is the descriptors still free when the fleet
 * starts less {@link #RESERVE} (less half of them when fewer than twice that are free), so that the live page's
 * connections (at most 256), hooks and the notification keep theirs; when an open fails for want of descriptors
 * anyway, the budget shrinks to what is open. A reserve rather than a share: with a limit of 20,000, half would
 * close and reopen files of 10,000 busy logs all the time.
 */
final class OpenFiles {

    /** Descriptors every fleet may hold, whatever the limit says. */
    private static final int FLOOR = 8;
    /** Descriptors left to the rest of the process when many are free. */
    static final int RESERVE = 1024;

    private int budget;
    private int open;
    /**
     * The logs holding files open. When each was last active is its {@link WatchedLog#active} stamp, and the logs are
     * ordered by it only when some must be closed: keeping them in order moved a log in a linked set at every poll
     * that read something (a remove and an add per record read, at robot pace).
     */
    private final Set<WatchedLog> holding = new HashSet<>();
    /** The last activity stamp given. */
    private long stamp;
    private boolean told;

    OpenFiles(int budget) {
        this.budget = Math.max(FLOOR, budget);
    }

    /**
     * The descriptors this process may still open less {@link #RESERVE} (half of them when fewer than twice the
     * reserve are free), or effectively no bound where that cannot be told.
     */
    static int defaultBudget() {
        OperatingSystemMXBean os = ManagementFactory.getOperatingSystemMXBean();
        if (os instanceof com.sun.management.UnixOperatingSystemMXBean unix) {
            long free = unix.getMaxFileDescriptorCount() - unix.getOpenFileDescriptorCount();
            return budget(free);
        }
        return Integer.MAX_VALUE;
    }

    /** The budget when {@code free} descriptors are free. */
    static int budget(long free) {
        return (int) Math.min(Integer.MAX_VALUE, Math.max(FLOOR, free - Math.min(free / 2, RESERVE)));
    }

    /** Whether {@code e} is an open that failed for want of descriptors (EMFILE, ENFILE). */
    static boolean exhausted(IOException e) {
        String why = e instanceof FileSystemException f ? f.getReason() : e.getMessage();
        return why != null && (why.contains("Too many open files") || why.contains("too many open files"));
    }

    int budget() {
        return budget;
    }

    int open() {
        return open;
    }

    /** After {@code log} was polled: counts what it holds open now; {@code active} when it had something new. */
    void polled(WatchedLog log, boolean active) {
        int now = log.watcher().openFiles();
        int before = log.openFiles;
        if (now != before) {
            open += now - before;
            log.openFiles = now;
            if (now == 0) {
                holding.remove(log);
            } else if (before == 0) {
                holding.add(log);
                active = true; // opened now: the latest active
            }
        }
        if (active) {
            log.active = ++stamp;
        }
    }

    /** A log is no longer followed (its files are closed). */
    void closed(WatchedLog log) {
        open -= log.openFiles;
        log.openFiles = 0;
        holding.remove(log);
    }

    /** Whether more files are open than the budget allows. */
    boolean over() {
        return open > budget;
    }

    /** An open failed for want of descriptors: from now on no more than are open now, less a margin. */
    void exhausted() {
        budget = Math.max(FLOOR, Math.min(budget, open - Math.max(1, open / 8)));
    }

    /**
     * Closes the files of the logs idle longest until the budget is kept with room to spare, sparing {@code keep};
     * a log whose replacement waits is not closed (its files cannot be reopened by path).
     *
     * @return whether this is the first time the fleet had to, so that it is said once
     */
    boolean relieve(WatchedLog keep) throws IOException {
        int target = budget - budget / 10;
        List<WatchedLog> byActivity = new ArrayList<>(holding);
        byActivity.sort(Comparator.comparingLong(l -> l.active)); // the one active longest ago first
        for (Iterator<WatchedLog> i = byActivity.iterator(); i.hasNext() && open > target; ) {
            WatchedLog log = i.next();
            if (log != keep && !log.watcher().replacing() && log.watcher().release()) {
                open -= log.openFiles;
                log.openFiles = log.watcher().openFiles();
                open += log.openFiles;
                if (log.openFiles == 0) {
                    holding.remove(log);
                }
            }
        }
        boolean first = !told;
        told = true;
        return first;
    }
}
