package dev.predmon.rosbag;

import java.nio.charset.StandardCharsets;

/**
 * Reads the primitives of one CDR (XCDR1) message: the 4-byte encapsulation header ({@code 00 01} little-endian,
 * {@code 00 00} big-endian, then two option bytes), then values aligned to their size counted from the byte after
 * that header. Every read is checked against the message's end, so a count or a length never makes it read, or
 * allocate, past the bytes there are.
 */
final class CdrReader {

    private final byte[] data;
    private final int origin;
    private final int end;
    private final boolean little;
    private int pos;

    /** The message in {@code data[offset, offset + length)}. */
    CdrReader(byte[] data, int offset, int length) throws CdrException {
        if (length < 4) {
            throw new CdrException("expected a 4-byte CDR encapsulation header, the message has " + length
                    + " byte(s)");
        }
        int kind = (data[offset] & 0xff) << 8 | (data[offset + 1] & 0xff);
        if (kind != 0 && kind != 1) {
            throw new CdrException(String.format("expected the CDR encapsulation 00 00 (big-endian) or 00 01 "
                    + "(little-endian), found %02x %02x", data[offset] & 0xff, data[offset + 1] & 0xff));
        }
        this.data = data;
        this.origin = offset + 4;
        this.end = offset + length;
        this.little = kind == 1;
        this.pos = origin;
    }

    /** Bytes left after the current position. */
    int remaining() {
        return end - pos;
    }

    /** The position, counted from the byte after the encapsulation header. */
    int position() {
        return pos - origin;
    }

    void align(int size) throws CdrException {
        int aligned = origin + ((pos - origin + size - 1) & -size);
        need(aligned - pos, "alignment padding");
        pos = aligned;
    }

    private void need(int n, String what) throws CdrException {
        if (n > end - pos) {
            throw new CdrException("expected " + what + " of " + n + " byte(s) at byte " + (pos - origin + 4)
                    + " of the message, which has " + (end - origin + 4));
        }
    }

    int u8() throws CdrException {
        need(1, "a byte");
        return data[pos++] & 0xff;
    }

    int i16() throws CdrException {
        align(2);
        need(2, "a 16-bit value");
        int v = little ? ((data[pos] & 0xff) | data[pos + 1] << 8) : (data[pos] << 8 | (data[pos + 1] & 0xff));
        pos += 2;
        return v;
    }

    int i32() throws CdrException {
        align(4);
        need(4, "a 32-bit value");
        int v = little
                ? ((data[pos] & 0xff) | (data[pos + 1] & 0xff) << 8 | (data[pos + 2] & 0xff) << 16 | data[pos + 3] << 24)
                : (data[pos] << 24 | (data[pos + 1] & 0xff) << 16 | (data[pos + 2] & 0xff) << 8 | (data[pos + 3] & 0xff));
        pos += 4;
        return v;
    }

    long i64() throws CdrException {
        align(8);
        need(8, "a 64-bit value");
        long v = 0;
        for (int i = 0; i < 8; i++) {
            int b = data[pos + (little ? 7 - i : i)] & 0xff;
            v = v << 8 | b;
        }
        pos += 8;
        return v;
    }

    /**
     * A count of elements (a sequence's or a string's), checked against the bytes left: each element takes at least
     * {@code minBytes}, so a count that cannot fit is an error here, before anything is allocated.
     */
    int count(String what, long minBytes) throws CdrException {
        int at = pos - origin + 4;
        long n = i32() & 0xffffffffL;
        if (n > 0 && (n > Integer.MAX_VALUE || n * minBytes > end - pos)) {
            throw new CdrException("impossible length " + n + " of " + what + " at byte " + at
                    + " of the message: only " + (end - pos) + " byte(s) follow");
        }
        return (int) n;
    }

    /** A string: a u32 length that counts the terminating NUL, the bytes, the NUL. */
    String string(String what, int bound) throws CdrException {
        int n = count(what, 1);
        if (n == 0) {
            return ""; // some writers give an empty string no terminator
        }
        if (bound > 0 && n - 1 > bound) {
            throw new CdrException(what + " has " + (n - 1) + " bytes, more than its bound " + bound);
        }
        int len = data[pos + n - 1] == 0 ? n - 1 : n;
        String s = new String(data, pos, len, StandardCharsets.UTF_8);
        pos += n;
        return s;
    }
}
