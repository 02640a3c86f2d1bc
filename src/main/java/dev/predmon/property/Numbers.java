package dev.predmon.property;

import java.math.BigDecimal;
import java.math.MathContext;

/**
 * Numbers as users read them in verdicts: {@code 20}, {@code 19.5}, {@code 9.956} (six significant digits); from
 * 10^15 on in scientific notation ({@code 1e308}), never a line of 309 digits.
 */
final class Numbers {
    private Numbers() {
    }

    static String text(double x) {
        if (x == Math.rint(x) && Math.abs(x) < 1e15) {
            return Long.toString((long) x);
        }
        BigDecimal six = new BigDecimal(x).round(new MathContext(6)).stripTrailingZeros();
        return Math.abs(x) >= 1e15 ? six.toString().replace("E+", "e") : six.toPlainString();
    }
}
