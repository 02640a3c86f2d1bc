package dev.predmon.parse;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * The last three lines of a text log, kept because a yarplogger save file whose version line was lost shows its
 * nature only at a start marker, and the entry's time stamps and level are the three lines before it. Lines given
 * as bytes are copied into reusable buffers, so remembering a line costs no allocation on the hot path.
 */
final class RecentLines {

    /** Longer byte lines are kept as strings rather than growing a buffer for ever. */
    private static final int MAX_BUFFERED = 4096;

    private final String[] text = new String[3];
    private byte[][] bytes = {new byte[128], new byte[128], new byte[128]};
    private final int[] length = new int[3];
    private final boolean[] present = new boolean[3];

    void push(String line) {
        shift();
        text[2] = line;
        present[2] = true;
    }

    /** Remembers an ASCII line given as bytes. */
    void push(byte[] b, int offset, int len) {
        if (len > MAX_BUFFERED) {
            push(new String(b, offset, len, StandardCharsets.ISO_8859_1));
            return;
        }
        shift();
        if (bytes[2].length < len) {
            bytes[2] = new byte[Math.max(len, bytes[2].length * 2)];
        }
        System.arraycopy(b, offset, bytes[2], 0, len);
        length[2] = len;
        text[2] = null;
        present[2] = true;
    }

    /** The k-th of the three lines (0 oldest), trimmed, or null when there is none. */
    String trimmed(int k) {
        if (!present[k]) {
            return null;
        }
        String s = text[k] != null ? text[k] : new String(bytes[k], 0, length[k], StandardCharsets.ISO_8859_1);
        return s.trim();
    }

    void clear() {
        Arrays.fill(text, null);
        Arrays.fill(present, false);
    }

    private void shift() {
        byte[] recycled = bytes[0];
        bytes = new byte[][] {bytes[1], bytes[2], recycled};
        text[0] = text[1];
        text[1] = text[2];
        length[0] = length[1];
        length[1] = length[2];
        present[0] = present[1];
        present[1] = present[2];
    }
}
