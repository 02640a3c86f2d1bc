package dev.predmon.monitor;

import java.nio.ByteBuffer;
import java.nio.file.Path;

/**
 * A directory watched through inotify ({@link InotifyWatch}): its key, and the file names that its events told of,
 * each with one {@link Path} and one write change made when the name is first seen, so that the thousandth write to
 * a log costs no new Path. A name is looked up where the kernel put it, in the read buffer: the kernel pads it with
 * NULs to a multiple of 16 bytes, so it is hashed and compared 8 bytes at a time, in an open-addressed table.
 */
final class InotifyDirectory implements DirectoryWatch.Key {

    /** Names kept per directory; beyond, the table starts anew (names of files long gone are not kept forever). */
    static final int MAX_NAMES = 1 << 16;

    /**
     * A file name seen in the directory: its Path, the change that tells a write to it, its padded bytes as 8-byte
     * words, and the count of takes when that change was last queued (the reading thread's alone).
     */
    static final class Name {
        final Path path;
        final DirectoryWatch.Change written;
        private final long[] words;
        long queued = -1;

        Name(Path path, DirectoryWatch.Change written, long[] words) {
            this.path = path;
            this.written = written;
            this.words = words;
        }

        boolean is(ByteBuffer events, int at, int len) {
            if (words.length * 8 != len) {
                return false;
            }
            for (int i = 0; i < words.length; i++) {
                if (words[i] != events.getLong(at + 8 * i)) {
                    return false;
                }
            }
            return true;
        }
    }

    final int wd;
    final Path dir;
    final DirectoryWatch.Change overflow;
    private final InotifyWatch watch;
    private volatile boolean valid = true;
    // The names, open-addressed by hash, half full at most: the reading thread's alone.
    private int[] hashes = new int[64];
    private Name[] slots = new Name[64];
    private int size;
    private final byte[] bytes = new byte[256];

    InotifyDirectory(InotifyWatch watch, int wd, Path dir) {
        this.watch = watch;
        this.wd = wd;
        this.dir = dir;
        this.overflow = new DirectoryWatch.Change(this, DirectoryWatch.Kind.OVERFLOW, null);
    }

    /**
     * The name of {@code len} bytes (NUL-padded to a multiple of 8) at {@code at} of {@code events}, or null when no
     * Path is these bytes (a name not valid in the system's encoding): then every log of the directory is to be
     * looked at.
     */
    Name name(ByteBuffer events, int at, int len) {
        if ((len & 7) != 0) {
            return spelled(events, at, len); // not as the kernel pads: looked up the slow way
        }
        long h = 0;
        for (int i = 0; i < len; i += 8) {
            h = (h ^ events.getLong(at + i)) * 0x9E3779B97F4A7C15L;
        }
        int hash = (int) (h ^ (h >>> 32));
        int mask = slots.length - 1;
        for (int i = hash & mask; ; i = (i + 1) & mask) {
            Name n = slots[i];
            if (n == null) {
                break;
            }
            if (hashes[i] == hash && n.is(events, at, len)) {
                return n;
            }
        }
        Name n = spelled(events, at, len);
        if (n != null) {
            if (size >= MAX_NAMES) {
                hashes = new int[64];
                slots = new Name[64];
                size = 0;
            }
            if (2 * (size + 1) > slots.length) {
                grow();
            }
            put(hash, n);
        }
        return n;
    }

    /** A new Name for the bytes at {@code at}, or null when no Path spells them. */
    private Name spelled(ByteBuffer events, int at, int len) {
        events.get(at, bytes, 0, len);
        int length = 0;
        while (length < len && bytes[length] != 0) {
            length++;
        }
        String s = Inotify.name(bytes, length);
        if (s == null) {
            return null;
        }
        long[] words = new long[len / 8];
        for (int i = 0; i < words.length; i++) {
            words[i] = events.getLong(at + 8 * i);
        }
        Path path = dir.getFileSystem().getPath(s);
        return new Name(path, new DirectoryWatch.Change(this, DirectoryWatch.Kind.MODIFIED, path), words);
    }

    private void put(int hash, Name n) {
        int mask = slots.length - 1;
        int i = hash & mask;
        while (slots[i] != null) {
            i = (i + 1) & mask;
        }
        slots[i] = n;
        hashes[i] = hash;
        size++;
    }

    private void grow() {
        int[] oldHashes = hashes;
        Name[] oldSlots = slots;
        hashes = new int[oldSlots.length * 2];
        slots = new Name[oldSlots.length * 2];
        size = 0;
        for (int i = 0; i < oldSlots.length; i++) {
            if (oldSlots[i] != null) {
                put(oldHashes[i], oldSlots[i]);
            }
        }
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
}
