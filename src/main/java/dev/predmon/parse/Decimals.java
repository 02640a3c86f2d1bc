package dev.predmon.parse;

/**
 * Reads the decimals a log's replies carry ({@code 87.5}, {@code -3}, {@code .25}, and YARP's 21 significant digits,
 * {@code 54.8510000000001127773}) exactly as {@link Double#parseDouble} does, but without its allocations: every
 * battery reply is read by its rule and by the safety monitor, and the JDK's parser took about 350 bytes and 300 ns
 * for each of YARP's 21-digit values, a third of what a large log's classification allocated.
 *
 * <p>How, for a decimal of up to 38 significant digits and at most 27 decimals (every sensor value a monitor prints):
 * <ul>
 *   <li>digits <= 2^53 and at most 22 decimals: integer and power of ten are exact doubles and their quotient is
 *       correctly rounded (Clinger's fast path);</li>
 *   <li>otherwise the digits N (up to 128 bits) are divided by 5^d (up to 64 bits; N / 10^d is N / 5^d * 2^-d)
 *       exactly in integers: a quotient of 63 or 64 bits, N * 2^s / 5^d, and whether a remainder is left. Rounding that quotient to 53 bits, to
 *       nearest with ties to even and the remainder as sticky bit, is the correctly rounded value, which is what
 *       {@code parseDouble} returns for any decimal.</li>
 * </ul>
 * Anything else in the grammar (an exponent, more digits or decimals) goes to {@code parseDouble}.
 */
public final class Decimals {

    private static final double[] POWERS_OF_TEN = new double[23];
    /** 5^k as unsigned 64-bit integers, k = 0..27 (5^27 < 2^64 < 5^28). */
    private static final long[] POWERS_OF_FIVE = new long[28];

    static {
        POWERS_OF_TEN[0] = 1;
        for (int k = 1; k < POWERS_OF_TEN.length; k++) {
            POWERS_OF_TEN[k] = POWERS_OF_TEN[k - 1] * 10;
        }
        POWERS_OF_FIVE[0] = 1;
        for (int k = 1; k < POWERS_OF_FIVE.length; k++) {
            POWERS_OF_FIVE[k] = POWERS_OF_FIVE[k - 1] * 5; // 5^27 is above 2^63: read as unsigned
        }
    }

    private static final int MAX_DIGITS = 38;

    private Decimals() {
    }

    /**
     * The value of {@code s} if it is a decimal number, {@code [+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?} (no blanks),
     * exactly {@link Double#parseDouble}'s; NaN for anything else.
     */
    public static double parse(String s) {
        int n = s.length();
        int i = n > 0 && (s.charAt(0) == '-' || s.charAt(0) == '+') ? 1 : 0;
        boolean negative = i == 1 && s.charAt(0) == '-';
        long hi = 0;
        long lo = 0;
        int significant = 0;
        int digits = 0;
        int decimals = -1;
        for (; i < n; i++) {
            char c = s.charAt(i);
            if (c >= '0' && c <= '9') {
                digits++;
                if (decimals >= 0) {
                    decimals++;
                }
                if (significant > 0 || c != '0') {
                    if (++significant <= MAX_DIGITS) {
                        // (hi, lo) = (hi, lo) * 10 + digit, unsigned 128-bit
                        long lo10 = lo * 10;
                        long carry = unsignedMultiplyHigh(lo, 10);
                        long sum = lo10 + (c - '0');
                        if (Long.compareUnsigned(sum, lo10) < 0) {
                            carry++;
                        }
                        hi = hi * 10 + carry;
                        lo = sum;
                    }
                }
            } else if (c == '.' && decimals < 0) {
                decimals = 0;
            } else if ((c == 'e' || c == 'E') && digits > 0) {
                return exponentTail(s, i + 1) ? Double.parseDouble(s) : Double.NaN;
            } else {
                return Double.NaN;
            }
        }
        if (digits == 0) {
            return Double.NaN;
        }
        int scale = Math.max(decimals, 0);
        if (significant > MAX_DIGITS || scale >= POWERS_OF_FIVE.length || (scale == 0 && hi != 0)) {
            return Double.parseDouble(s);
        }
        double value = exact(hi, lo, scale);
        if (Double.isNaN(value)) {
            return Double.parseDouble(s); // too many digits before the point for one 64-bit quotient
        }
        return negative ? -value : value;
    }

    /** Whether {@code s} from {@code i} is an exponent's {@code [+-]?\d+}. */
    private static boolean exponentTail(String s, int i) {
        int n = s.length();
        if (i < n && (s.charAt(i) == '-' || s.charAt(i) == '+')) {
            i++;
        }
        if (i == n) {
            return false;
        }
        for (; i < n; i++) {
            if (s.charAt(i) < '0' || s.charAt(i) > '9') {
                return false;
            }
        }
        return true;
    }

    /**
     * The double nearest to N / 10^scale, N the unsigned 128-bit (hi, lo), scale <= 27; NaN if N is too large. As
     * N / 10^scale = (N / 5^scale) * 2^-scale and scaling by a power of two is exact, the division is by 5^scale.
     */
    private static double exact(long hi, long lo, int scale) {
        if (hi == 0 && lo >= 0 && lo <= (1L << 53) && scale < POWERS_OF_TEN.length) {
            return scale > 0 ? lo / POWERS_OF_TEN[scale] : (double) lo;
        }
        long p = POWERS_OF_FIVE[scale];
        int bitsN = hi != 0 ? 128 - Long.numberOfLeadingZeros(hi) : 64 - Long.numberOfLeadingZeros(lo);
        int bitsP = 64 - Long.numberOfLeadingZeros(p);
        // N * 2^shift / p then lies in (2^62, 2^64): a quotient of 63 or 64 bits
        int shift = 63 + bitsP - bitsN;
        long q;
        boolean sticky;
        if (scale == 0 && hi == 0) {
            q = lo; // an integer beyond 2^53: only rounding is left
            shift = 0;
            sticky = false;
        } else {
            if (shift < 0) {
                return Double.NaN; // N above 2^(63 + bits of p): the caller takes the JDK's parser
            }
            long h;
            long l;
            if (shift == 0) {
                h = hi;
                l = lo;
            } else if (shift < 64) {
                h = (hi << shift) | (lo >>> (64 - shift));
                l = lo << shift;
            } else {
                h = lo << (shift - 64);
                l = 0;
            }
            // (h, l) / p, h < p: restoring division, one quotient bit per step
            long r = h;
            q = 0;
            for (int bit = 63; bit >= 0; bit--) {
                boolean overflow = r < 0;
                r = (r << 1) | ((l >>> bit) & 1);
                q <<= 1;
                if (overflow || Long.compareUnsigned(r, p) >= 0) {
                    r -= p;
                    q |= 1;
                }
            }
            sticky = r != 0;
        }
        int bitsQ = 64 - Long.numberOfLeadingZeros(q);
        int drop = bitsQ - 53;
        if (drop <= 0) {
            return Math.scalb((double) q, -shift - scale);
        }
        long mantissa = q >>> drop;
        long rest = q & ((1L << drop) - 1);
        long half = 1L << (drop - 1);
        if (rest > half || (rest == half && (sticky || (mantissa & 1) != 0))) {
            mantissa++;
            if (mantissa == 1L << 53) {
                mantissa >>>= 1;
                drop++;
            }
        }
        return Math.scalb((double) mantissa, drop - shift - scale);
    }

    /** The high 64 bits of the unsigned 128-bit product (Java 18 has it as {@code Math.unsignedMultiplyHigh}). */
    private static long unsignedMultiplyHigh(long a, long b) {
        return Math.multiplyHigh(a, b) + ((a >> 63) & b) + ((b >> 63) & a);
    }
}
