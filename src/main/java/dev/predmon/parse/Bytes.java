package dev.predmon.parse;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;

/**
 * Scans of byte runs eight bytes at a time ("SWAR": a {@code long} read from the array, bytes tested with bit
 * arithmetic): finding the end of a line and checking that a field value is plain ASCII were the parser's largest
 * costs, one byte and one branch at a time over every byte of a log.
 *
 * <p>{@code hasZero(x)} is the classic test {@code (x - 0x01..01) & ~x & 0x80..80}: non-zero exactly when a byte of
 * {@code x} is zero, and its lowest set bit marks the lowest such byte (a borrow only propagates upwards).
 */
final class Bytes {

    private static final VarHandle LONGS = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);
    private static final long ONES = 0x0101010101010101L;
    private static final long HIGHS = 0x8080808080808080L;
    private static final long NEWLINES = ONES * '\n';
    private static final long ANGLES = ONES * '<';
    private static final long ESCAPES = ONES * 0x1b;

    private Bytes() {
    }

    /** The index of the first {@code '\n'} in {@code b[from, to)}, or -1. */
    static int indexOfNewline(byte[] b, int from, int to) {
        int i = from;
        for (; i + 8 <= to; i += 8) {
            long zero = hasZero((long) LONGS.get(b, i) ^ NEWLINES);
            if (zero != 0) {
                return i + (Long.numberOfTrailingZeros(zero) >>> 3);
            }
        }
        for (; i < to; i++) {
            if (b[i] == '\n') {
                return i;
            }
        }
        return -1;
    }

    /**
     * Whether {@code b[from, to)} is plain ASCII without {@code '<'} (a save file's marker) and without ESC (a colour
     * code): what a field value on the parser's fast path may hold.
     */
    static boolean plain(byte[] b, int from, int to) {
        int i = from;
        for (; i + 8 <= to; i += 8) {
            long w = (long) LONGS.get(b, i);
            if ((w & HIGHS) != 0 || (hasZero(w ^ ANGLES) | hasZero(w ^ ESCAPES)) != 0) {
                return false;
            }
        }
        for (; i < to; i++) {
            if (b[i] < 0 || b[i] == '<' || b[i] == 0x1b) {
                return false;
            }
        }
        return true;
    }

    /** Whether {@code b[from, to)} is plain ASCII without {@code '<'}; colour codes allowed. */
    static boolean asciiWithoutAngle(byte[] b, int from, int to) {
        int i = from;
        for (; i + 8 <= to; i += 8) {
            long w = (long) LONGS.get(b, i);
            if ((w & HIGHS) != 0 || hasZero(w ^ ANGLES) != 0) {
                return false;
            }
        }
        for (; i < to; i++) {
            if (b[i] < 0 || b[i] == '<') {
                return false;
            }
        }
        return true;
    }

    private static long hasZero(long x) {
        return (x - ONES) & ~x & HIGHS;
    }
}
