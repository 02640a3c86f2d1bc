package dev.predmon.abstraction;

/**
 * Reads the plain decimals a log's replies carry ({@code 87.5}, {@code -3}, {@code .25}) without the regex and the
 * JDK's general parser, which allocate on every call: every battery reply is read by the rule, the noise estimate
 * and the safety monitor. The value is exactly {@link Double#parseDouble}'s: with at most 2^53 as the digits'
 * integer and at most 22 decimals, integer and power of ten are exact doubles and their quotient is correctly
 * rounded (Clinger's fast path). Anything else is left to the caller's general path.
 */
final class Decimals {

    private static final double[] POWERS_OF_TEN = new double[23];

    static {
        POWERS_OF_TEN[0] = 1;
        for (int k = 1; k < POWERS_OF_TEN.length; k++) {
            POWERS_OF_TEN[k] = POWERS_OF_TEN[k - 1] * 10;
        }
    }

    private Decimals() {
    }

    /**
     * The value of {@code s} if it is a plain decimal ({@code [+-]?\d*\.?\d*} with a digit, at most 18 digits and
     * 22 decimals, digits at most 2^53), else NaN: the caller then takes its general path.
     */
    static double plain(String s) {
        int n = s.length();
        int i = n > 0 && (s.charAt(0) == '-' || s.charAt(0) == '+') ? 1 : 0;
        long digits = 0;
        int count = 0;
        int decimals = -1;
        for (; i < n; i++) {
            char c = s.charAt(i);
            if (c >= '0' && c <= '9') {
                if (++count > 18) {
                    return Double.NaN;
                }
                digits = digits * 10 + (c - '0');
                if (decimals >= 0) {
                    decimals++;
                }
            } else if (c == '.' && decimals < 0) {
                decimals = 0;
            } else {
                return Double.NaN;
            }
        }
        if (count == 0 || digits > (1L << 53) || decimals >= POWERS_OF_TEN.length) {
            return Double.NaN;
        }
        double value = decimals > 0 ? digits / POWERS_OF_TEN[decimals] : (double) digits;
        return s.charAt(0) == '-' ? -value : value;
    }
}
