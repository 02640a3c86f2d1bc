package dev.predmon.monitor;

import com.sun.jna.Memory;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import static dev.predmon.monitor.Inotify.CLOEXEC;
import static dev.predmon.monitor.Inotify.EAGAIN;
import static dev.predmon.monitor.Inotify.EINTR;
import static dev.predmon.monitor.Inotify.IN_ATTRIB;
import static dev.predmon.monitor.Inotify.IN_CREATE;
import static dev.predmon.monitor.Inotify.IN_DELETE;
import static dev.predmon.monitor.Inotify.IN_IGNORED;
import static dev.predmon.monitor.Inotify.IN_MODIFY;
import static dev.predmon.monitor.Inotify.IN_MOVED_FROM;
import static dev.predmon.monitor.Inotify.IN_MOVED_TO;
import static dev.predmon.monitor.Inotify.IN_MOVE_SELF;
import static dev.predmon.monitor.Inotify.IN_Q_OVERFLOW;
import static dev.predmon.monitor.Inotify.NONBLOCK;
import static dev.predmon.monitor.Inotify.POLLIN;

/**
 * Linux's inotify, read by predmon itself (through JNA) rather than through the JDK's watch service, which wakes its
 * thread for every few events, allocates a Path and an event per event, and holds at most 512 events per directory.
 * One inotify instance, one watch per directory. The reading thread ({@code predmon-notify}) sleeps in poll() while
 * nothing happens; once events come, it drains the kernel's queue in reads of up to {@link #BUFFER} bytes (about
 * 2,000 events each), hands what it read to {@link #take}, and pauses {@link #READ_PAUSE_NANOS} before the next
 * drain, so that the events of a millisecond cost one read however many there are. A file name is looked up by its
 * bytes in its directory's table ({@link InotifyDirectory}): no Path per event, and a log written many times in one
 * drain is queued once.
 *
 * <p>When the kernel's queue overflowed ({@code fs.inotify.max_queued_events}, often 16,384, events unread), every
 * directory is told as overflowed, and every log of it is looked at. A directory moved away under its watch is no
 * longer watched (the watch would follow it): its key turns invalid at once, and its logs are taken from the path
 * again, as when it is deleted.
 */
final class InotifyWatch extends DirectoryWatch {

    /** The C library that has inotify's calls. */
    static final String LIBRARY = "c";
    /** The size of one read of the kernel's queue. */
    static final int BUFFER = 64 * 1024;
    /** The largest event: its 16-byte header and a name of 255 bytes with its NUL. */
    private static final int LARGEST_EVENT = 16 + 256;

    private final int fd;
    /** An eventfd that {@link #close} writes to, to end the reading thread's poll(). */
    private final int wake;
    /** The watched directories by watch descriptor; guarded by itself. */
    private final Map<Integer, InotifyDirectory> byWd = new HashMap<>();
    private final Thread reader;
    private volatile boolean closed;
    /** While set, the reading thread reads nothing (tests let the kernel's queue fill). */
    private volatile boolean held;

    private InotifyWatch(int fd, int wake) {
        this.fd = fd;
        this.wake = wake;
        reader = new Thread(this::read, "predmon-notify");
        reader.setDaemon(true);
        reader.start();
    }

    /**
     * predmon's own inotify reader, or null where it cannot be had: not Linux, JNA or {@code library} not loadable,
     * or no inotify instance (the JDK's watch service then says why, or works where this failed).
     */
    static DirectoryWatch open(String library) {
        if (!Inotify.bind(library)) {
            return null;
        }
        try {
            int fd = Inotify.inotify_init1(NONBLOCK | CLOEXEC);
            if (fd < 0) {
                return null;
            }
            int wake = Inotify.eventfd(0, NONBLOCK | CLOEXEC);
            if (wake < 0) {
                Inotify.close(fd);
                return null;
            }
            return new InotifyWatch(fd, wake);
        } catch (LinkageError | RuntimeException e) {
            return null; // a C library without inotify's calls
        }
    }

    @Override
    Key register(Path dir) throws IOException {
        if (closed) {
            throw new IOException("the notification is closed");
        }
        synchronized (byWd) {
            int wd = Inotify.inotify_add_watch(fd, Inotify.spelling(dir), Inotify.MASK);
            if (wd < 0) {
                throw Inotify.registerFailed(dir, Inotify.errno());
            }
            // The same directory under another spelling is the same watch descriptor: the same key.
            InotifyDirectory d = byWd.get(wd);
            if (d == null || !d.isValid()) {
                d = new InotifyDirectory(this, wd, dir);
                byWd.put(wd, d);
            }
            return d;
        }
    }

    /** Removes {@code d}'s watch; the kernel's last event for it ({@code IN_IGNORED}) then forgets it. */
    void cancel(InotifyDirectory d) {
        synchronized (byWd) {
            if (!closed) {
                Inotify.inotify_rm_watch(fd, d.wd);
            }
        }
    }

    /** Stops or resumes reading, for tests: events meanwhile wait in the kernel's queue. */
    void hold(boolean hold) {
        held = hold;
    }

    private void read() {
        Memory buffer = new Memory(BUFFER);
        ByteBuffer events = buffer.getByteBuffer(0, BUFFER).order(ByteOrder.nativeOrder());
        Memory fds = new Memory(16);
        fds.setInt(0, fd);
        fds.setShort(4, POLLIN);
        fds.setInt(8, wake);
        fds.setShort(12, POLLIN);
        Events parsed = new Events();
        try {
            while (!closed) {
                if (held) {
                    TimeUnit.NANOSECONDS.sleep(READ_PAUSE_NANOS);
                    continue;
                }
                boolean any = false;
                while (true) {
                    long n = Inotify.read(fd, buffer, BUFFER);
                    if (n < 0) {
                        int errno = Inotify.errno();
                        if (errno == EINTR) {
                            continue;
                        }
                        if (errno != EAGAIN) {
                            throw new IllegalStateException("reading inotify: " + Inotify.message(errno));
                        }
                        break;
                    }
                    any = true;
                    parsed.parse(events, (int) n);
                    if (n <= BUFFER - LARGEST_EVENT) {
                        break; // the queue was emptied: had more been waiting, the read would have filled the buffer
                    }
                }
                if (any) {
                    queue(parsed.batch, parsed.gone, true);
                    parsed.batch.clear();
                    parsed.gone.clear();
                    // The events of the next millisecond gather in the kernel's queue: one read for all of them.
                    TimeUnit.NANOSECONDS.sleep(READ_PAUSE_NANOS);
                } else if (Inotify.poll(fds, 2, -1) < 0 && Inotify.errno() != EINTR) {
                    throw new IllegalStateException("waiting for inotify: " + Inotify.message(Inotify.errno()));
                }
            }
        } catch (InterruptedException stop) {
            // closed
        } catch (RuntimeException | Error e) {
            if (!closed) {
                failed(e);
            }
        }
    }

    /** The events of one drain, read into changes for {@link #queue}. */
    private final class Events {
        final List<Change> batch = new ArrayList<>();
        final List<Key> gone = new ArrayList<>();
        private InotifyDirectory last;
        private long takes;

        void parse(ByteBuffer events, int n) {
            takes = takes(); // read after the events: see takes()
            int p = 0;
            while (p + 16 <= n) {
                int wd = events.getInt(p);
                int mask = events.getInt(p + 4);
                int len = events.getInt(p + 12);
                int at = p + 16;
                p = at + len;
                if ((mask & IN_Q_OVERFLOW) != 0) {
                    synchronized (byWd) { // events were lost, of any directory
                        byWd.values().forEach(d -> batch.add(d.overflow));
                    }
                    continue;
                }
                InotifyDirectory d = last != null && last.wd == wd ? last : directory(wd);
                if (d == null) {
                    continue; // removed already
                }
                last = d;
                if ((mask & IN_IGNORED) != 0) { // deleted, moved (below), unmounted or cancelled: no more events
                    synchronized (byWd) {
                        byWd.remove(wd, d);
                    }
                    d.invalidate();
                    gone.add(d);
                    last = null;
                } else if ((mask & IN_MOVE_SELF) != 0) {
                    d.cancel(); // the watch would follow the directory away from its logs' paths
                } else if (len > 0 && d.isValid()) {
                    named(d, mask, events, at, len);
                }
            }
        }

        private void named(InotifyDirectory d, int mask, ByteBuffer events, int at, int len) {
            InotifyDirectory.Name n = d.name(events, at, len);
            if (n == null) {
                batch.add(d.overflow); // a name no Path spells: every log of the directory is looked at
            } else if ((mask & (IN_MODIFY | IN_ATTRIB)) != 0) {
                if (n.queued != takes) { // else queued already, not taken yet: one read takes both writes
                    n.queued = takes;
                    batch.add(n.written);
                }
            } else if ((mask & (IN_CREATE | IN_MOVED_TO)) != 0) {
                batch.add(new Change(d, Kind.CREATED, n.path));
            } else if ((mask & (IN_DELETE | IN_MOVED_FROM)) != 0) {
                batch.add(new Change(d, Kind.DELETED, n.path));
            }
        }

        private InotifyDirectory directory(int wd) {
            synchronized (byWd) {
                return byWd.get(wd);
            }
        }
    }

    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        Memory one = new Memory(8);
        one.setLong(0, 1);
        Inotify.write(wake, one, 8);
        reader.interrupt();
        // Closing is how following ends, often on an interrupted thread: the join waits all the same (the reader
        // is ending within a millisecond), and the interrupt status is kept.
        boolean interrupted = false;
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (reader.isAlive() && deadline - System.nanoTime() > 0) {
            try {
                reader.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        if (!reader.isAlive()) { // else its descriptors stay open rather than be closed under it
            synchronized (byWd) {
                Inotify.close(fd);
                Inotify.close(wake);
            }
        }
    }
}
