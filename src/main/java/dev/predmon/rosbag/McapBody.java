package dev.predmon.rosbag;

import java.nio.charset.StandardCharsets;

/**
 * Reads the fields of one MCAP record body (little-endian integers, u32-length-prefixed strings and byte arrays),
 * each read checked against the body's end.
 */
final class McapBody {

    /** A body that ends before one of its fields; the message says which. */
    static final class Truncated extends Exception {
        private static final long serialVersionUID = 1L;

        Truncated(String message) {
            super(message);
        }
    }

    final byte[] data;
    int pos;
    final int end;

    McapBody(byte[] data, int pos, int end) {
        this.data = data;
        this.pos = pos;
        this.end = end;
    }

    private void need(long n, String what) throws Truncated {
        if (n > end - pos) {
            throw new Truncated("expected " + what + " of " + n + " byte(s), the record has " + (end - pos) + " left");
        }
    }

    int u16(String what) throws Truncated {
        need(2, what);
        int v = (data[pos] & 0xff) | (data[pos + 1] & 0xff) << 8;
        pos += 2;
        return v;
    }

    long u32(String what) throws Truncated {
        need(4, what);
        long v = le32(data, pos);
        pos += 4;
        return v;
    }

    long u64(String what) throws Truncated {
        need(8, what);
        long v = le64(data, pos);
        pos += 8;
        return v;
    }

    String string(String what) throws Truncated {
        long n = u32("the length of " + what);
        need(n, what);
        String s = new String(data, pos, (int) n, StandardCharsets.UTF_8);
        pos += (int) n;
        return s;
    }

    /** Skips a u32-length-prefixed field (a map or byte array). */
    void skip(String what) throws Truncated {
        long n = u32("the length of " + what);
        need(n, what);
        pos += (int) n;
    }

    static long le32(byte[] b, int at) {
        return (b[at] & 0xffL) | (b[at + 1] & 0xffL) << 8 | (b[at + 2] & 0xffL) << 16 | (b[at + 3] & 0xffL) << 24;
    }

    static long le64(byte[] b, int at) {
        return le32(b, at) | le32(b, at + 4) << 32;
    }
}
