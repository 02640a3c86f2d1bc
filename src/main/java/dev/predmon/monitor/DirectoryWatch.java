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
 * instance ({@code fs.inotify.max_user_instances} is often 128 per user).
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

    private final WatchService service;

    private DirectoryWatch(WatchService service) {
        this.service = service;
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
     * Each directory's key is reset before its changes are handed out, so that a write after this call signals
     * again even while the caller is still reading the file: no write goes unannounced.
     *
     * @param invalid receives the keys of directories that are no longer watched (deleted, unmounted)
     * @return the changes, empty when none came in time
     */
    List<Change> take(long nanos, List<WatchKey> invalid) throws InterruptedException {
        List<Change> out = new ArrayList<>();
        WatchKey key = nanos > 0 ? service.poll(nanos, TimeUnit.NANOSECONDS) : service.poll();
        while (key != null) {
            for (WatchEvent<?> e : key.pollEvents()) {
                WatchEvent.Kind<?> kind = e.kind();
                if (kind == OVERFLOW) {
                    out.add(new Change(key, Kind.OVERFLOW, null));
                } else {
                    out.add(new Change(key, kind == ENTRY_CREATE ? Kind.CREATED
                            : kind == ENTRY_DELETE ? Kind.DELETED : Kind.MODIFIED, (Path) e.context()));
                }
            }
            if (!key.reset()) {
                invalid.add(key);
            }
            key = service.poll();
        }
        return out;
    }

    @Override
    public void close() throws IOException {
        service.close();
    }
}
