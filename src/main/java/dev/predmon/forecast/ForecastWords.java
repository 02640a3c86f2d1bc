package dev.predmon.forecast;

import java.math.BigDecimal;
import java.math.RoundingMode;

/**
 * A forecast in words an operator reads at a glance.
 *
 * <p>Numbers are written by {@link #fixed}, not {@code String.format}: a warning's words are built on the poll that
 * read its record, and a {@code Formatter} (a new one per call, with its locale's symbols) made up about two thirds
 * of what the forecast added to that poll ({@code bench --only latency}).
 */
public final class ForecastWords {

    private ForecastWords() {
    }

    /** {@code P(violation) 0.93}. */
    public static String probability(Forecast f) {
        return "P(violation) " + fixed(f.probability(), 2);
    }

    /** {@code about 8.3 s (8.2-9.0 s)}, {@code about 48 ticks (30 ticks or more)}, or {@code no violation in sight}. */
    public static String time(Forecast f) {
        if (!inSight(f)) {
            return "no violation in sight";
        }
        String unit = f.unit();
        String range = f.low() == null ? "" : f.high() == null
                ? " (" + amount(f.low()) + " " + unit + " or more)"
                : " (" + amount(f.low()) + "-" + amount(f.high()) + " " + unit + ")";
        return "about " + amount(f.timeToViolation()) + " " + unit + " to the violation" + range;
    }

    /**
     * Whether a violation is in sight: a time to it, and a probability that does not read as 0 beside it (a
     * {@code P(violation) 0.00} has no time to a violation, whatever the survival curve's median says).
     */
    public static boolean inSight(Forecast f) {
        return f.timeToViolation() != null && f.probability() >= 0.005;
    }

    /**
     * Why the forecast says what it says: how many training runs were where this run is and how many violated, what the
     * property reads and how fast it moves, and whether the run has done something new.
     */
    public static String evidence(Forecast f) {
        return evidence(f, false);
    }

    /** As above, of a ceiling when {@code ceiling}: the training runs went as high as its value. */
    public static String evidence(Forecast f, boolean ceiling) {
        StringBuilder b = new StringBuilder();
        switch (f.basis()) {
            case MATCHED -> b.append(f.violated()).append(" of ").append(f.runs())
                    .append(" training runs that were in this state");
            case RESYNCHRONISED -> b.append(f.violated()).append(" of ").append(f.runs())
                    .append(" training runs in the states the latest steps lead to");
            case VALUE_ONLY, BASE_RATE -> b.append(f.violated()).append(" of ").append(f.runs())
                    .append(" training runs");
            case VIOLATED -> {
                return "the property is violated";
            }
            default -> throw new IllegalStateException(f.basis().toString());
        }
        if (f.value() != null) {
            b.append(ceiling ? " and went as high as " : " and went as low as ").append(fixed(f.value(), 2));
        }
        b.append(" violated");
        if (f.drift() != null && f.value() != null) {
            b.append("; the value ").append(fixed(f.value(), 2)).append(f.drift() < 0 ? " falls " : " rises ")
                    .append(amount(Math.abs(f.drift()))).append(" per ").append(f.unit().equals("s") ? "s" : "tick");
        }
        if (f.novel()) {
            b.append("; novel behaviour since line ").append(f.novelSince()).append(" (")
                    .append(f.basis() == Forecast.Basis.BASE_RATE ? "no learned state fits: the base rate speaks"
                            : f.basis() == Forecast.Basis.VALUE_ONLY ? "no learned state fits: the value alone speaks"
                            : "matching resumed on the latest steps").append(')');
        }
        return b.toString();
    }

    /**
     * The forecast in a few words, for a line under each pair: {@code P(violation) 0.34, about 76.0 s to the violation
     * (49.6-162 s) [matched, 10 of 29 runs]}, and {@code novel since line N} when it is.
     */
    public static String brief(Forecast f) {
        String runs = f.basis() == Forecast.Basis.VIOLATED ? ""
                : ", " + f.violated() + " of " + f.runs() + " runs";
        return probability(f) + ", " + time(f) + " [" + f.basis().label() + runs + "]"
                + (f.novel() ? "; novel since line " + f.novelSince() : "");
    }

    /** The whole forecast on one line. */
    public static String line(Forecast f) {
        return probability(f) + ", " + time(f) + " [" + f.basis().label() + "]: " + evidence(f);
    }

    private static String amount(double x) {
        return fixed(x, Math.abs(x) >= 100 ? 0 : Math.abs(x) >= 10 ? 1 : 2);
    }

    /**
     * {@code x} with {@code digits} decimals, as {@code String.format(Locale.ROOT, "%.<digits>f", x)} writes it: the
     * shortest decimal that reads back as {@code x}, rounded half up, with its sign kept when it rounds to zero.
     */
    public static String fixed(double x, int digits) {
        if (!Double.isFinite(x)) {
            return Double.isNaN(x) ? "NaN" : x > 0 ? "Infinity" : "-Infinity";
        }
        String s = BigDecimal.valueOf(x).setScale(digits, RoundingMode.HALF_UP).toPlainString();
        return (x < 0 || Double.compare(x, -0.0) == 0) && s.charAt(0) != '-' ? "-" + s : s;
    }
}
