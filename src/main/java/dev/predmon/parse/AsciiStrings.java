package dev.predmon.parse;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Strings for short ASCII byte runs, reusing the one built before for the same bytes. The fields of a monitor log
 * repeat a handful of values (ports, protocols, commands, locations, acknowledgement codes) on every record, so most
 * values of a record come from here instead of a new allocation.
 *
 * <p>Bounded: a fixed two-way table where a new value replaces an old one. A value is only admitted the second time
 * its hash misses in its set, so values that never repeat (sensor readings, tick numbers) do not evict the ones that
 * do; and the hash covers every byte, because ports of one robot differ in their middles
 * ({@code /GoToDestination/BT_rpc/client}, {@code /IsAtDestination/BT_rpc/client}): a hash of a few sampled bytes made
 * them evict each other on every record, a third of a large log's allocation. A collision costs one allocation,
 * never a wrong string, since the bytes are compared in full.
 *
 * <p>One table per thread ({@link #local()}), shared by every parser on it: the logs of a fleet repeat the same
 * values, and one warm table serves thousands of logs read in turn, where a table per log was cold at every record
 * (its compares were a sixth of a fleet's following time at robot pace) and cost a few KB per log.
 */
final class AsciiStrings {

    private static final ThreadLocal<AsciiStrings> LOCAL = ThreadLocal.withInitial(AsciiStrings::new);

    private static final int SETS = 512;
    private static final int MAX_CACHED = 64;

    /** Two ways per set: slots {@code 2 * set} and {@code 2 * set + 1}. */
    private final String[] strings = new String[2 * SETS];
    private final byte[][] keys = new byte[2 * SETS][];
    /** Per set, the hash of the last value that missed there; a second miss with it admits the value. */
    private final int[] missed = new int[SETS];

    /** This thread's table. */
    static AsciiStrings local() {
        return LOCAL.get();
    }

    /** The string of {@code len} ASCII bytes of {@code b} from {@code offset}. */
    String of(byte[] b, int offset, int len) {
        if (len == 0) {
            return "";
        }
        if (len > MAX_CACHED) {
            return new String(b, offset, len, StandardCharsets.ISO_8859_1);
        }
        int end = offset + len;
        int h = len;
        for (int i = offset; i < end; i++) {
            h = 31 * h + b[i];
        }
        return lookUp(b, offset, len, h);
    }

    /**
     * {@link #of}, or null when the bytes are not plain ASCII without {@code '<'} and ESC ({@link Bytes#plain}):
     * checked while hashing, in the same pass over the bytes.
     */
    String ofPlain(byte[] b, int offset, int len) {
        if (len == 0) {
            return "";
        }
        int end = offset + len;
        if (len > MAX_CACHED) {
            return Bytes.plain(b, offset, end) ? new String(b, offset, len, StandardCharsets.ISO_8859_1) : null;
        }
        int h = len;
        boolean plain = true;
        for (int i = offset; i < end; i++) {
            byte c = b[i];
            plain &= c >= 0 && c != '<' && c != 0x1b;
            h = 31 * h + c;
        }
        return plain ? lookUp(b, offset, len, h) : null;
    }

    private String lookUp(byte[] b, int offset, int len, int h) {
        int end = offset + len;
        h ^= h >>> 15;
        int set = h & (SETS - 1);
        int slot = 2 * set;
        byte[] key = keys[slot];
        if (key != null && Arrays.equals(key, 0, key.length, b, offset, end)) {
            return strings[slot];
        }
        key = keys[slot + 1];
        if (key != null && Arrays.equals(key, 0, key.length, b, offset, end)) {
            return strings[slot + 1];
        }
        String s = new String(b, offset, len, StandardCharsets.ISO_8859_1);
        if (missed[set] != h) {
            missed[set] = h; // seen once: admitted if it comes again
            return s;
        }
        // The newer entry goes to way 0, the older moves to way 1: the least recently admitted one leaves.
        keys[slot + 1] = keys[slot];
        strings[slot + 1] = strings[slot];
        keys[slot] = Arrays.copyOfRange(b, offset, end);
        strings[slot] = s;
        return s;
    }
}
