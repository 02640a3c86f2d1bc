package dev.predmon.monitor;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.ClosedWatchServiceException;
import java.nio.file.FileSystemException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.WatchEvent;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import static java.nio.file.StandardWatchEventKinds.ENTRY_CREATE;
import static java.nio.file.StandardWatchEventKinds.ENTRY_DELETE;
import static java.nio.file.StandardWatchEventKinds.ENTRY_MODIFY;
import static java.nio.file.StandardWatchEventKinds.OVERFLOW;

/**
 * The operating system's file-change notification (inotify on Linux, through {@link WatchService}) for the
 * directories of a fleet's logs. Directories, not files, are watched: one inotify watch per directory however many
 * logs it holds (the per-user limit, {@code fs.inotify.max_user_watches}, is often 8192), and a directory's watch
 * also tells of files created, renamed or deleted in it, which rotation does. A whole fleet shares one inotify
 * instance ({@code fs.inotify.max_user_instances} is often 128 per user). A thread of its own ({@code predmon-notify})
 * takes the JDK's changes as they come, once a millisecond at most, and queues them for {@link #take}: the JDK holds
 * 512 changes per directory, beyond which it reports an overflow.
 *
 * <p>The caller polls instead where a notification would not be trusted: a directory on a network or FUSE file
 * system ({@link #remote}: inotify only sees changes made through this machine's kernel, not a writer on another
 * host), and where {@link #register} fails: a directory that does not exist or cannot be read, or the watch limit
 * reached. {@link #open} gives none where the JDK's watch service itself polls (it looks every 2 to 10 seconds,
 * too slow for a warning), or cannot be had.
 */
final class DirectoryWatch implements AutoCloseable {

    /** File system types whose changes by other hosts inotify does not see (as named in /proc/mounts). */
    private static final Set<String> NETWORK = Set.of("nfs", "nfs4", "cifs", "smb", "smb2", "smb3", "smbfs", "9p",
            "ceph", "glusterfs", "lustre", "gpfs", "afs", "ncpfs", "davfs", "vboxsf", "vmhgfs", "virtiofs");

    /** What happened in a watched directory. */
    enum Kind { CREATED, DELETED, MODIFIED, OVERFLOW }

    /**
     * One change: {@code name} (a file name, relative to the directory) was created (or renamed to), deleted (or
     * renamed away) or written; {@code OVERFLOW}, with no name, when events were lost and anything may have changed.
     */
    record Change(WatchKey key, Kind kind, Path name) {
    }

    /** Changes queued for {@link #take} beyond which a directory's further creations and deletions are an overflow. */
    static final int MAX_QUEUED = 1 << 16;
    /** The reading thread's pause after each take of the JDK's changes. */
    static final long READ_PAUSE_NANOS = 1_000_000L;

    private final WatchService service;
    private final Object lock = new Object();
    /** Changes read and not yet taken, in order; guarded by {@link #lock}. */
    private List<Change> queued = new ArrayList<>();
    /** The writes and overflows among {@link #queued}: each once. */
    private final Set<Change> modified = new HashSet<>();
    private final List<WatchKey> queuedInvalid = new ArrayList<>();
    /** Whether {@link #take} waits for a change. */
    private boolean waiting;
    private RuntimeException failure;

    private DirectoryWatch(WatchService service) {
        this.service = service;
        Thread reader = new Thread(this::read, "predmon-notify");
        reader.setDaemon(true);
        reader.start();
    }

    /** The file system's notification, or null where there is none worth having (the caller then polls). */
    static DirectoryWatch open() {
        return open(why -> { });
    }

    /**
     * The file system's notification, or null where there is none worth having: then {@code unavailable} is told
     * why, in a few words, and the caller polls.
     */
    static DirectoryWatch open(Consumer<String> unavailable) {
        WatchService service;
        try {
            service = FileSystems.getDefault().newWatchService();
        } catch (IOException e) {
            unavailable.accept(why(e)); // e.g. "User limit of inotify instances reached": polling works the same
            return null;
        } catch (UnsupportedOperationException e) {
            unavailable.accept("not supported by the default file system");
            return null;
        }
        if (service.getClass().getSimpleName().startsWith("Polling")) {
            try {
                service.close();
            } catch (IOException ignored) {
                // nothing was registered with it
            }
            unavailable.accept("the JDK's watch service only polls here, every 2 to 10 s");
            return null;
        }
        return new DirectoryWatch(service);
    }

    /**
     * Watches {@code dir} for files created, deleted and written in it; the same directory under another spelling
     * (a symbolic link) gives the same key. Whether its file system notifies is for {@link #remote} to say first.
     *
     * @return the key its changes will carry
     * @throws IOException when its changes must be polled for: it is gone or unreadable, or the watch limit is
     *                     reached ({@link #why} says which)
     */
    WatchKey register(Path dir) throws IOException {
        try {
            return dir.register(service, ENTRY_CREATE, ENTRY_DELETE, ENTRY_MODIFY);
        } catch (UnsupportedOperationException e) {
            throw new IOException("not supported by its file system", e);
        } catch (ClosedWatchServiceException e) {
            throw new IOException("the notification is closed", e);
        }
    }

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
     * Waits up to {@code nanos} for changes, then takes every change already signalled without waiting more.
     * Each directory's key is reset before its changes are handed out (by the reading thread, as soon as the JDK
     * signals it), so that a write after this call signals again even while the caller is still reading the file: no
     * write goes unannounced.
     *
     * @param invalid receives the keys of directories that are no longer watched (deleted, unmounted)
     * @return the changes, empty when none came in time
     */
    List<Change> take(long nanos, List<WatchKey> invalid) throws InterruptedException {
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
            modified.clear();
            invalid.addAll(queuedInvalid);
            queuedInvalid.clear();
            return out;
        }
    }

    /**
     * The reading thread: takes each key as soon as the JDK signals it, resets it, and queues its changes for
     * {@link #take}, a write to a file already queued as written counted once. The JDK holds at most 512 changes per
     * directory between two takes and turns the rest into an overflow, after which every log of the directory must be
     * looked at: 10,000 logs written at a robot's pace fill that in 2 ms, less than the following thread spends
     * reading what one wakeup brought. Taken here at once, they overflow only when the following thread lags by
     * {@link #MAX_QUEUED} changes.
     */
    private void read() {
        List<Change> batch = new ArrayList<>();
        List<WatchKey> gone = new ArrayList<>();
        try {
            while (true) {
                WatchKey key = service.take();
                while (key != null) {
                    for (WatchEvent<?> e : key.pollEvents()) {
                        WatchEvent.Kind<?> kind = e.kind();
                        batch.add(kind == OVERFLOW ? new Change(key, Kind.OVERFLOW, null)
                                : new Change(key, kind == ENTRY_CREATE ? Kind.CREATED
                                : kind == ENTRY_DELETE ? Kind.DELETED : Kind.MODIFIED, (Path) e.context()));
                    }
                    if (!key.reset()) {
                        gone.add(key);
                    }
                    key = service.poll();
                }
                queue(batch, gone);
                batch.clear();
                gone.clear();
                // The changes of the next millisecond gather in the JDK's lists (far from 512 per directory at
                // 270,000 writes a second): one wakeup of this thread per millisecond, not one per write.
                TimeUnit.NANOSECONDS.sleep(READ_PAUSE_NANOS);
            }
        } catch (ClosedWatchServiceException | InterruptedException closed) {
            // closed: following ended
        } catch (RuntimeException | Error e) {
            synchronized (lock) {
                failure = new IllegalStateException("the file-change notification failed", e);
                lock.notifyAll();
            }
        }
    }

    private void queue(List<Change> batch, List<WatchKey> gone) {
        synchronized (lock) {
            boolean was = queued.isEmpty() && queuedInvalid.isEmpty();
            for (Change c : batch) {
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

    @Override
    public void close() throws IOException {
        service.close();
    }
}
