package dev.predmon.monitor;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * A directory watched through inotify ({@link InotifyWatch}): its key, and the file names that its events told of,
 * each with one {@link Path} and one write change made when the name is first seen, so that the thousandth write to
 * a log costs no new Path: the name's bytes are looked up in place.
 */
final class InotifyDirectory implements DirectoryWatch.Key {

    /** Names kept per directory; beyond, the table starts anew (names of files long gone are not kept forever). */
    static final int MAX_NAMES = 1 << 16;

    /** A file name seen in the directory: its Path, and the change that tells a write to it. */
    record Name(Path path, DirectoryWatch.Change written) {
    }

    final int wd;
    final Path dir;
    final DirectoryWatch.Change overflow;
    private final InotifyWatch watch;
    private volatile boolean valid = true;
    /** The names by their bytes: the reading thread's alone. */
    private final Map<Bytes, Name> names = new HashMap<>();
    private final Bytes probe = new Bytes(null, 0);

    InotifyDirectory(InotifyWatch watch, int wd, Path dir) {
        this.watch = watch;
        this.wd = wd;
        this.dir = dir;
        this.overflow = new DirectoryWatch.Change(this, DirectoryWatch.Kind.OVERFLOW, null);
    }

    /**
     * The name in {@code bytes[0, length)}, or null when no Path is these bytes (a name not valid in the system's
     * encoding): then every log of the directory is to be looked at.
     */
    Name name(byte[] bytes, int length) {
        probe.set(bytes, length);
        Name known = names.get(probe);
        if (known != null) {
            return known;
        }
        String s = Inotify.name(bytes, length);
        if (s == null) {
            return null;
        }
        if (names.size() >= MAX_NAMES) {
            names.clear();
        }
        Path path = dir.getFileSystem().getPath(s);
        Name n = new Name(path, new DirectoryWatch.Change(this, DirectoryWatch.Kind.MODIFIED, path));
        names.put(new Bytes(Arrays.copyOf(bytes, length), length), n);
        return n;
    }

    /** The name in {@code bytes[0, length)} is gone from the directory: its entry need not be kept. */
    void forget(byte[] bytes, int length) {
        probe.set(bytes, length);
        names.remove(probe);
    }

    /** The watch is gone (the directory deleted, moved or unmounted, or the key cancelled). */
    void invalidate() {
        valid = false;
    }

    @Override
    public boolean isValid() {
        return valid;
    }

    @Override
    public void cancel() {
        if (valid) {
            valid = false;
            watch.cancel(this);
        }
    }

    /** A name's bytes as a map key; the probe is set in place for each lookup. */
    private static final class Bytes {
        private byte[] b;
        private int length;
        private int hash;

        Bytes(byte[] b, int length) {
            if (b != null) {
                set(b, length);
            }
        }

        void set(byte[] bytes, int n) {
            b = bytes;
            length = n;
            int h = 1;
            for (int i = 0; i < n; i++) {
                h = 31 * h + bytes[i];
            }
            hash = h;
        }

        @Override
        public int hashCode() {
            return hash;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Bytes other && other.hash == hash
                    && Arrays.equals(b, 0, length, other.b, 0, other.length);
        }
    }
}
