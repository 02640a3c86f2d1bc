package dev.predmon.parse;

import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The header's time read from bytes is exactly what {@link Double#parseDouble} reads from the same text. */
class DecimalTimeTest {

    private static void same(String text) {
        byte[] b = ("  " + text + " ").getBytes(StandardCharsets.ISO_8859_1);
        double fast = ColumnsLayout.decimal(b, 2, 2 + text.length());
        assertEquals(Double.doubleToRawLongBits(Double.parseDouble(text)), Double.doubleToRawLongBits(fast), text);
    }

    @Test
    void handPickedTimes() {
        for (String t : new String[] {"0", "-0", "0.0", "-0.0", "5.", ".5", "71.818968", "1.314327", "0001.5000",
                "1700000000.123456", "1700000000.1234567", "9007199254740992", "9007199254740993",
                "123456789012345678", "1234567890123456789", "0.0000000000000000000001", "0.00000000000000000000001",
                "-12.25", "99999999999999999999.5"}) {
            same(t);
        }
    }

    @Test
    void randomTimes() {
        Random random = new Random(12);
        for (int i = 0; i < 200_000; i++) {
            StringBuilder s = new StringBuilder();
            if (random.nextInt(10) == 0) {
                s.append('-');
            }
            int whole = random.nextInt(12);
            int fraction = random.nextInt(12);
            for (int k = 0; k < whole; k++) {
                s.append((char) ('0' + random.nextInt(10)));
            }
            if (fraction > 0 || whole == 0) {
                s.append('.');
                for (int k = 0; k < Math.max(fraction, whole == 0 ? 1 : 0); k++) {
                    s.append((char) ('0' + random.nextInt(10)));
                }
            }
            same(s.toString());
        }
    }
}
