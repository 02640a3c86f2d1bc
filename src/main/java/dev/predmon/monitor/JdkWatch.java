package dev.predmon.monitor;

import java.io.IOException;
import java.nio.file.ClosedWatchServiceException;
import java.nio.file.FileSystems;
import java.nio.file.Path;
import java.nio.file.WatchEvent;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import static java.nio.file.StandardWatchEventKinds.ENTRY_CREATE;
import static java.nio.file.StandardWatchEventKinds.ENTRY_DELETE;
import static java.nio.file.StandardWatchEventKinds.ENTRY_MODIFY;
import static java.nio.file.StandardWatchEventKinds.OVERFLOW;

/**
 * The notification through the JDK's {@link WatchService}: where predmon's own inotify reader cannot be had (another
 * system, no native library). The JDK holds 512 changes per directory, beyond which it reports an overflow, so its
 * changes are taken as soon as it signals them, by a thread of its own.
 */
final class JdkWatch extends DirectoryWatch {

    /** A directory's key: equal for equal JDK keys, so that a change may carry a new one. */
    private record JdkKey(WatchKey key) implements Key {
        @Override
        public boolean isValid() {
            return key.isValid();
        }

        @Override
        public void cancel() {
            key.cancel();
        }
    }

    private final WatchService service;

    private JdkWatch(WatchService service) {
        this.service = service;
        Thread reader = new Thread(this::read, "predmon-notify");
        reader.setDaemon(true);
        reader.start();
    }

    /** The JDK's notification, or null (then {@code unavailable} is told why) where it cannot be had or only polls. */
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
        return new JdkWatch(service);
    }

    @Override
    Key register(Path dir) throws IOException {
        try {
            return new JdkKey(dir.register(service, ENTRY_CREATE, ENTRY_DELETE, ENTRY_MODIFY));
        } catch (UnsupportedOperationException e) {
            throw new IOException("not supported by its file system", e);
        } catch (ClosedWatchServiceException e) {
            throw new IOException("the notification is closed", e);
        }
    }

    /**
     * The reading thread: takes each key as soon as the JDK signals it, resets it (so that a later write signals
     * again), and queues its changes. The JDK holds at most 512 changes per directory between two takes and turns
     * the rest into an overflow: 10,000 logs written at a robot's pace fill that in 2 ms, less than the following
     * thread spends reading what one wakeup brought; taken here at once, they do not overflow.
     */
    private void read() {
        List<Change> batch = new ArrayList<>();
        List<Key> gone = new ArrayList<>();
        try {
            while (true) {
                WatchKey key = service.take();
                while (key != null) {
                    JdkKey k = new JdkKey(key);
                    for (WatchEvent<?> e : key.pollEvents()) {
                        WatchEvent.Kind<?> kind = e.kind();
                        batch.add(kind == OVERFLOW ? new Change(k, Kind.OVERFLOW, null)
                                : new Change(k, kind == ENTRY_CREATE ? Kind.CREATED
                                : kind == ENTRY_DELETE ? Kind.DELETED : Kind.MODIFIED, (Path) e.context()));
                    }
                    if (!key.reset()) {
                        gone.add(k);
                    }
                    key = service.poll();
                }
                queue(batch, gone, false);
                batch.clear();
                gone.clear();
                // The changes of the next millisecond gather in the JDK's lists (far from 512 per directory at
                // 270,000 writes a second): one wakeup of this thread per millisecond, not one per write.
                TimeUnit.NANOSECONDS.sleep(READ_PAUSE_NANOS);
            }
        } catch (ClosedWatchServiceException | InterruptedException closed) {
            // closed: following ended
        } catch (RuntimeException | Error e) {
            failed(e);
        }
    }

    @Override
    public void close() throws IOException {
        service.close();
    }
}
