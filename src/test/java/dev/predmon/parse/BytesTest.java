package dev.predmon.parse;

import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The eight-bytes-at-a-time scans give what a byte-by-byte loop gives, at every offset and length. */
class BytesTest {

    private static int slowNewline(byte[] b, int from, int to) {
        for (int i = from; i < to; i++) {
            if (b[i] == '\n') {
                return i;
            }
        }
        return -1;
    }

    private static boolean slowPlain(byte[] b, int from, int to, boolean escapeToo) {
        for (int i = from; i < to; i++) {
            if (b[i] < 0 || b[i] == '<' || (escapeToo && b[i] == 0x1b)) {
                return false;
            }
        }
        return true;
    }

    @Test
    void sameAsByteByByte() {
        Random random = new Random(3);
        byte[] special = {'\n', '<', 0x1b, (byte) 0x80, (byte) 0xff, (byte) 0xc3, 0x0b, 0x3b, 0x3d, 0x09, 0x1a, 0x1c};
        for (int round = 0; round < 20_000; round++) {
            byte[] b = new byte[1 + random.nextInt(40)];
            for (int i = 0; i < b.length; i++) {
                b[i] = random.nextInt(6) == 0 ? special[random.nextInt(special.length)] : (byte) (' ' + random.nextInt(90));
            }
            int from = random.nextInt(b.length);
            int to = from + random.nextInt(b.length - from + 1);
            assertEquals(slowNewline(b, from, to), Bytes.indexOfNewline(b, from, to));
            assertEquals(slowPlain(b, from, to, true), Bytes.plain(b, from, to));
            assertEquals(slowPlain(b, from, to, false), Bytes.asciiWithoutAngle(b, from, to));
        }
    }
}
