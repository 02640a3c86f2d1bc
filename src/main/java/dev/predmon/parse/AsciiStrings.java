package dev.predmon.parse;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Strings for short ASCII byte runs, reusing the last one built for the same bytes. The fields of a monitor log
 * repeat a handful of values (ports, protocols, commands, locations) on every record, so most values of a
 * record come from here instead of a new allocation. Bounded: a fixed table where a new value replaces an old.
 * The hash looks at the length, both ends and the middle only (cheap; a collision costs one allocation, never a
 * wrong string, since the bytes are compared in full).
 */
final class AsciiStrings {

    private static final int SLOTS = 1024;
    private static final int MAX_CACHED = 64;

    private final String[] strings = new String[SLOTS];
    private final byte[][] keys = new byte[SLOTS][];

    /** The string of {@code len} ASCII bytes of {@code b} from {@code offset}. */
    String of(byte[] b, int offset, int len) {
        if (len == 0) {
            return "";
        }
        if (len > MAX_CACHED) {
            return new String(b, offset, len, StandardCharsets.ISO_8859_1);
        }
        int end = offset + len;
        if (isDigit(b[offset]) && isDigit(b[end - 1])) {
            // A number (a tick, a sensor reading): they seldom repeat, and caching one costs a copy and a compare.
            return new String(b, offset, len, StandardCharsets.ISO_8859_1);
        }
        int h = len * 31 + b[offset] * 7 + b[end - 1] * 131 + b[offset + len / 2] * 17 + b[end - 1 - len / 3] * 5;
        int slot = (h ^ (h >>> 7)) & (SLOTS - 1);
        byte[] key = keys[slot];
        if (key != null && Arrays.equals(key, 0, key.length, b, offset, end)) {
            return strings[slot];
        }
        String s = new String(b, offset, len, StandardCharsets.ISO_8859_1);
        keys[slot] = Arrays.copyOfRange(b, offset, end);
        strings[slot] = s;
        return s;
    }

    private static boolean isDigit(byte c) {
        return c >= '0' && c <= '9';
    }
}
