package dev.predmon.rosbag;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Writes one little-endian CDR (XCDR1) message: the encapsulation header {@code 00 01 00 00}, then values aligned to
 * their size counted from the byte after it, as the ROS 2 middleware and {@code rosbags} write them.
 */
final class CdrWriter {

    private byte[] buf = new byte[256];
    private int pos;

    CdrWriter() {
        buf[1] = 1;
        pos = 4;
    }

    private void room(int n) {
        if (pos + n > buf.length) {
            buf = Arrays.copyOf(buf, Math.max(buf.length * 2, pos + n));
        }
    }

    void align(int size) {
        int aligned = 4 + ((pos - 4 + size - 1) & -size);
        room(aligned - pos);
        pos = aligned; // padding stays zero: the buffer starts zeroed and only grows
    }

    void u8(int v) {
        room(1);
        buf[pos++] = (byte) v;
    }

    void i16(int v) {
        align(2);
        room(2);
        buf[pos++] = (byte) v;
        buf[pos++] = (byte) (v >> 8);
    }

    void i32(int v) {
        align(4);
        room(4);
        for (int i = 0; i < 4; i++) {
            buf[pos++] = (byte) (v >> (8 * i));
        }
    }

    void i64(long v) {
        align(8);
        room(8);
        for (int i = 0; i < 8; i++) {
            buf[pos++] = (byte) (v >> (8 * i));
        }
    }

    void string(String s) {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        i32(b.length + 1);
        room(b.length + 1);
        System.arraycopy(b, 0, buf, pos, b.length);
        pos += b.length;
        buf[pos++] = 0;
    }

    byte[] bytes() {
        return Arrays.copyOf(buf, pos);
    }
}
