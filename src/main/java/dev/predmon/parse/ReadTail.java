package dev.predmon.parse;

import java.util.Arrays;

/**
 * The last bytes a {@link LogFollower} read from a file, to notice that the file was truncated and written again
 * past the old read position between two looks (copytruncate rotation while the logger writes): the bytes before the
 * read position are then no longer those read there.
 */
final class ReadTail {

    /** How many of the last bytes read are kept: enough for a time stamp and more. */
    private static final int BYTES = 64;

    /** The bytes just before the read position, as read: {@code tail[0, length)}. */
    private final byte[] tail = new byte[BYTES];
    private int length;

    /** Keeps the last {@value #BYTES} bytes read, the {@code n} bytes of {@code bytes} being the newest. */
    void remember(byte[] bytes, int n) {
        remember(bytes, 0, n);
    }

    /** Keeps the last {@value #BYTES} bytes read, the {@code n} bytes of {@code bytes} from {@code from} the newest. */
    void remember(byte[] bytes, int from, int n) {
        if (n >= BYTES) {
            System.arraycopy(bytes, from + n - BYTES, tail, 0, BYTES);
            length = BYTES;
            return;
        }
        int keep = Math.min(length, BYTES - n);
        System.arraycopy(tail, length - keep, tail, 0, keep);
        System.arraycopy(bytes, from, tail, keep, n);
        length = keep + n;
    }

    /** How many bytes before the read position are kept. */
    int length() {
        return length;
    }

    /** Whether the first {@link #length()} bytes of {@code bytes}, read from before the position, are those kept. */
    boolean matches(byte[] bytes) {
        return Arrays.equals(bytes, 0, length, tail, 0, length);
    }

    /** Reading starts over (from 0, or in another file). */
    void clear() {
        length = 0;
    }
}
