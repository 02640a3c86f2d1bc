package dev.predmon.parse;

import org.junit.jupiter.api.Test;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Random;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A decimal read without the JDK parser is bit for bit what {@link Double#parseDouble} reads. */
class DecimalsTest {

    private static final Pattern GRAMMAR =
            Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");

    private static void same(String text) {
        double expected = GRAMMAR.matcher(text).matches() ? Double.parseDouble(text) : Double.NaN;
        assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(Decimals.parse(text)), text);
    }

    @Test
    void handPicked() {
        for (String t : new String[] {"0", "-0", "+0", "-0.0", "87.5", "5.", ".5", "-.5", "100", "19.999999999999999",
                "9007199254740992", "9007199254740993", "123456789012345678", "0.0000000000000000000001",
                "0.00000000000000000000001", "54.8510000000001127773", "97.316999999987189085", "100.0",
                "20.000000000000000000", "19.9999999999999999999", "1e5", "1.5E-3", "-2e+2",
                "18446744073709551615", "18446744073709551616", "123456789012345678901234567890",
                "1234567890123456789012.5", "0.1234567890123456789", "9.9999999999999999999"}) {
            same(t);
        }
        for (String t : new String[] {"", "-", "+", ".", "-.", "NaN", "Infinity", "1.2.3", " 1", "1 ", "0x10",
                "1d", "1e", "1e+", "e5", ".e5", "1f"}) {
            assertTrue(Double.isNaN(Decimals.parse(t)), t);
        }
    }

    /** Exact midpoints between two doubles: ties go to the even mantissa, a digit more decides the other way. */
    @Test
    void tiesRoundToEven() {
        for (long m : new long[] {(1L << 53) + 1, (1L << 53) + 3, (1L << 54) + 2, (1L << 54) + 6, (1L << 62) + 1024}) {
            same(Long.toString(m));
        }
        // (2^53 + 1) / 2^k written out in decimal: each is a midpoint at a smaller scale
        for (int k = 1; k <= 19; k++) {
            String tie = new BigDecimal((1L << 53) + 1).divide(BigDecimal.valueOf(2).pow(k)).toPlainString();
            if (tie.replace(".", "").replaceFirst("^0+", "").length() <= 38 && tie.indexOf('.') >= tie.length() - 20) {
                same(tie);
                same(tie + "1");
            }
        }
    }

    @Test
    void randomDecimals() {
        Random random = new Random(7);
        String alphabet = "0123456789.-+";
        for (int i = 0; i < 300_000; i++) {
            StringBuilder s = new StringBuilder();
            int n = 1 + random.nextInt(24);
            for (int k = 0; k < n; k++) {
                s.append(k > 0 && random.nextInt(3) > 0 ? (char) ('0' + random.nextInt(10))
                        : alphabet.charAt(random.nextInt(alphabet.length())));
            }
            same(s.toString());
        }
    }

    /** What YARP prints: a double's exact binary value rounded to 21 significant digits. */
    @Test
    void yarpDoubles() {
        Random random = new Random(11);
        MathContext yarp = new MathContext(21);
        for (int i = 0; i < 300_000; i++) {
            double v = switch (i % 3) {
                case 0 -> random.nextDouble() * 100;
                case 1 -> random.nextGaussian() * 1e6;
                default -> Double.longBitsToDouble(random.nextLong() & 0x7fefffffffffffffL) / 1e290;
            };
            same(new BigDecimal(v).round(yarp).stripTrailingZeros().toPlainString());
            same(new BigDecimal(v).round(new MathContext(1 + random.nextInt(30))).toPlainString());
        }
    }
}
