package dev.predmon.abstraction;

import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A plain decimal read without the JDK parser is bit for bit what {@link Double#parseDouble} reads. */
class DecimalsTest {

    private static void same(String text) {
        double plain = Decimals.plain(text);
        if (!Double.isNaN(plain)) {
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(text)), Double.doubleToRawLongBits(plain), text);
        }
    }

    @Test
    void handPicked() {
        for (String t : new String[] {"0", "-0", "+0", "87.5", "5.", ".5", "-.5", "100", "19.999999999999999",
                "9007199254740992", "9007199254740993", "123456789012345678", "0.0000000000000000000001",
                "0.00000000000000000000001"}) {
            same(t);
        }
        for (String t : new String[] {"", "-", "+", ".", "-.", "1e5", "NaN", "Infinity", "1.2.3", " 1", "1 ", "0x10",
                "1d", "1234567890123456789"}) {
            assertTrue(Double.isNaN(Decimals.plain(t)), t);
        }
    }

    @Test
    void randomDecimals() {
        Random random = new Random(7);
        String alphabet = "0123456789.-+";
        for (int i = 0; i < 300_000; i++) {
            StringBuilder s = new StringBuilder();
            int n = 1 + random.nextInt(20);
            for (int k = 0; k < n; k++) {
                s.append(k > 0 && random.nextInt(3) > 0 ? (char) ('0' + random.nextInt(10))
                        : alphabet.charAt(random.nextInt(alphabet.length())));
            }
            String text = s.toString();
            try {
                Double.parseDouble(text);
            } catch (NumberFormatException e) {
                assertTrue(Double.isNaN(Decimals.plain(text)), text);
                continue;
            }
            same(text);
        }
    }
}
