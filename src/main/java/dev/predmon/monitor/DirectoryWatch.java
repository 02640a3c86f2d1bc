package dev.predmon.monitor;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * The operating system's file-change notification for the directories of a fleet's logs: on Linux inotify, read by
 * a reader of predmon's own ({@link InotifyWatch}), elsewhere, or where that reader cannot be had, the JDK's
 * {@link java.nio.file.WatchService} ({@link JdkWatch}). Directories, not files, are watched: one inotify watch per
 * directory however many logs it holds (the per-user limit, {@code fs.inotify.max_user_watches}, is often 8192), and
 * a directory's watch also tells of files created, renamed or deleted in it, which rotation does. A whole fleet shares
 * one inotify instance ({@code fs.inotify.max_user_instances} is often 128 per user). A thread of its own
 * ({@code predmon-notify}) reads the changes as they come, once a millisecond at most, and queues them for
 * {@link #take}.
 *
 * <p>The caller polls instead where a notification would not be trusted: a directory on a network or FUSE file
 * system ({@link #remote}: inotify only sees changes made through this machine's kernel, not a writer on another
 * host), and where {@link #register} fails: a directory that does not exist or cannot be read, or the watch limit
 * reached. {@link #open} gives none where the JDK's watch service itself polls (it looks every 2 to 10 seconds,
 * too slow for a warning), or cannot be had.
 */
abstract class DirectoryWatch implements AutoCloseable {

    /** File system types whose changes by other hosts inotify does not see (as named in /proc/mounts). */
    private static final Set<String> NETWORK = Set.of("nfs", "nfs4", "cifs", "smb", "smb2", "smb3", "smbfs", "9p",
            "ceph", "glusterfs", "lustre", "gpfs", "afs", "ncpfs", "davfs", "vboxsf", "vmhgfs", "virtiofs");
    /** {@code -Dpredmon.notify=jdk} takes the JDK's watch service even where predmon's own inotify reader works. */
    static final String NOTIFY_PROPERTY = "predmon.notify";

    /** What happened in a watched directory. */
    enum Kind { CREATED, DELETED, MODIFIED, OVERFLOW }

    /** A watched directory, as {@link #register} gave it. */
    interface Key {
        /** Whether its changes are still told: false once the directory is gone, or the key cancelled. */
        boolean isValid();

        /** Watches the directory no more. */
        void cancel();
    }

    /**
     * One change: {@code name} (a file name, relative to the directory) was created (or renamed to), deleted (or
     * renamed away) or written; {@code OVERFLOW}, with no name, when events were lost and anything may have changed.
     */
    record Change(Key key, Kind kind, Path name) {
    }

    /** Changes queued for {@link #take} beyond which a directory's further creations and deletions are an overflow. */
    static final int MAX_QUEUED = 1 << 16;
    /** The reading thread's pause after each take of the changes, while changes keep coming. */
    static final long READ_PAUSE_NANOS = 1_000_000L;

    private final Object lock = new Object();
    /** Changes read and not yet taken, in order; guarded by {@link #lock}. */
    private List<Change> queued = new ArrayList<>();
    /** The writes and overflows among {@link #queued}: each once. */
    private final Set<Change> modified = new HashSet<>();
    private final List<Key> queuedInvalid = new ArrayList<>();
    /** How many times {@link #take} took the queue: a write marked as queued since the last take is queued. */
    private volatile long takes;
    /** Whether {@link #take} waits for a change. */
    private boolean waiting;
    private RuntimeException failure;

    /** The file system's notification, or null where there is none worth having (the caller then polls). */
    static DirectoryWatch open() {
        return open(why -> { });
    }

    /**
     * The file system's notification, or null where there is none worth having: then {@code unavailable} is told
     * why, in a few words, and the caller polls. predmon's own inotify reader where it can be had, else the JDK's.
     */
    static DirectoryWatch open(Consumer<String> unavailable) {
        return open(unavailable, InotifyWatch.LIBRARY);
    }

    /** As {@link #open(Consumer)}, with inotify's calls taken from the C library of that name. */
    static DirectoryWatch open(Consumer<String> unavailable, String library) {
        if (!"jdk".equals(System.getProperty(NOTIFY_PROPERTY))) {
            DirectoryWatch own = InotifyWatch.open(library);
            if (own != null) {
                return own;
            }
        }
        return JdkWatch.open(unavailable);
    }

    /**
     * Watches {@code dir} for files created, deleted and written in it; the same directory under another spelling
     * (a symbolic link) gives the same key. Whether its file system notifies is for {@link #remote} to say first.
     *
     * @return the key its changes will carry
     * @throws IOException when its changes must be polled for: it is gone or unreadable, or the watch limit is
     *                     reached ({@link #why} says which)
     */
    abstract Key register(Path dir) throws IOException;

    /** Ends the notification: no change is read after. */
    @Override
    public abstract void close() throws IOException;

    /** Why {@code e} denied a notification, in a few words (a file system exception's message is only its path). */
    static String why(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileSystemException f) {
            return f.getReason() != null ? f.getReason() : f.getClass().getSimpleName();
        }
        return e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
    }

    /**
     * Whether {@code dir} is on a file system whose changes inotify may not see (network, FUSE), or null when that
     * cannot be told now (the directory does not exist yet).
     */
    static Boolean remote(Path dir) {
        try {
            return !notifies(Files.getFileStore(dir).type());
        } catch (IOException e) {
            return null;
        }
    }

    /** Whether inotify sees every change on a file system of this type. */
    static boolean notifies(String fileSystemType) {
        String type = fileSystemType.toLowerCase(Locale.ROOT);
        return !NETWORK.contains(type) && !(type.startsWith("fuse") && !type.equals("fuseblk"));
    }

    /** The identity of the directory at {@code dir} now, to notice that it was replaced under a watch, or null. */
    static Object identity(Path dir) {
        try {
            BasicFileAttributes a = Files.readAttributes(dir, BasicFileAttributes.class);
            return a.fileKey() != null ? a.fileKey() : a.creationTime();
        } catch (IOException e) {
            return null;
        }
    }

    /**
     * Waits up to {@code nanos} for changes, then takes every change already read without waiting more. A write
     * after the reading thread read the last change is announced again, even while the caller is still reading the
     * file: no write goes unannounced.
     *
     * @param invalid receives the keys of directories that are no longer watched (deleted, moved, unmounted)
     * @return the changes, empty when none came in time
     */
    List<Change> take(long nanos, List<Key> invalid) throws InterruptedException {
        synchronized (lock) {
            long deadline = System.nanoTime() + nanos;
            while (queued.isEmpty() && queuedInvalid.isEmpty() && failure == null) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    break;
                }
                waiting = true;
                try {
                    TimeUnit.NANOSECONDS.timedWait(lock, left);
                } finally {
                    waiting = false;
                }
            }
            if (failure != null) {
                throw failure;
            }
            List<Change> out = queued;
            queued = new ArrayList<>();
            takes++;
            modified.clear();
            invalid.addAll(queuedInvalid);
            queuedInvalid.clear();
            return out;
        }
    }

    /**
     * How many times the queue was taken. A reading thread that read a write after its file's last write was queued
     * while this count has not changed since, need not queue it again: the earlier one is not taken yet (or is in
     * its own batch), and the file is read after this write in any case, since the count changes before the take
     * returns.
     */
    final long takes() {
        return takes;
    }

    /**
     * Queues what the reading thread read for {@link #take}: a write to a file already queued as written counted
     * once, and beyond {@link #MAX_QUEUED} changes (the following thread lagging far behind) a directory's further
     * creations and deletions as one overflow, after which every log of it is looked at.
     *
     * @param unique the batch's writes are not queued already (the reading thread saw to it with {@link #takes})
     */
    final void queue(List<Change> batch, List<? extends Key> gone, boolean unique) {
        synchronized (lock) {
            boolean was = queued.isEmpty() && queuedInvalid.isEmpty();
            for (Change c : batch) {
                if (c.kind() == Kind.MODIFIED && unique) {
                    queued.add(c);
                    continue;
                }
                if (c.kind() == Kind.MODIFIED || c.kind() == Kind.OVERFLOW) {
                    if (!modified.add(c)) {
                        continue; // queued already: one read takes both writes
                    }
                } else if (queued.size() >= MAX_QUEUED) {
                    Change lost = new Change(c.key(), Kind.OVERFLOW, null);
                    if (modified.add(lost)) {
                        queued.add(lost);
                    }
                    continue;
                }
                queued.add(c);
            }
            queuedInvalid.addAll(gone);
            if (was && waiting && !(queued.isEmpty() && queuedInvalid.isEmpty())) {
                lock.notifyAll();
            }
        }
    }

    /** The reading thread failed: the next {@link #take} throws. */
    final void failed(Throwable e) {
        synchronized (lock) {
            failure = new IllegalStateException("the file-change notification failed", e);
            lock.notifyAll();
        }
    }
}
