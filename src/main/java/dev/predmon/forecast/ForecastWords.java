package dev.predmon.forecast;

import java.util.Locale;

/** A forecast in words an operator reads at a glance. */
public final class ForecastWords {

    private ForecastWords() {
    }

    /** {@code P(violation) 0.93}. */
    public static String probability(Forecast f) {
        return String.format(Locale.ROOT, "P(violation) %.2f", f.probability());
    }

    /** {@code about 8.3 s (8.2-9.0 s)}, {@code about 48 ticks (30 ticks or more)}, or {@code no violation in sight}. */
    public static String time(Forecast f) {
        if (f.timeToViolation() == null) {
            return "no violation in sight";
        }
        String unit = f.unit();
        String range = f.low() == null ? "" : f.high() == null
                ? String.format(Locale.ROOT, " (%s %s or more)", amount(f.low()), unit)
                : String.format(Locale.ROOT, " (%s-%s %s)", amount(f.low()), amount(f.high()), unit);
        return "about " + amount(f.timeToViolation()) + " " + unit + " to the violation" + range;
    }

    /**
     * Why the forecast says what it says: how many training runs were where this run is and how many violated, what the
     * property reads and how fast it moves, and whether the run has done something new.
     */
    public static String evidence(Forecast f) {
        StringBuilder b = new StringBuilder();
        switch (f.basis()) {
            case MATCHED -> b.append(String.format(Locale.ROOT, "%d of %d training runs that were in this state",
                    f.violated(), f.runs()));
            case RESYNCHRONISED -> b.append(String.format(Locale.ROOT,
                    "%d of %d training runs in the states the latest steps lead to", f.violated(), f.runs()));
            case VALUE_ONLY -> b.append(String.format(Locale.ROOT, "%d of %d training runs", f.violated(), f.runs()));
            case VIOLATED -> {
                return "the property is violated";
            }
            default -> throw new IllegalStateException(f.basis().toString());
        }
        if (f.value() != null) {
            b.append(String.format(Locale.ROOT, " and went as low as %.2f", f.value()));
        }
        b.append(" violated");
        if (f.drift() != null && f.value() != null) {
            b.append(String.format(Locale.ROOT, "; the value %.2f %s %s per %s", f.value(),
                    f.drift() < 0 ? "falls" : "rises", amount(Math.abs(f.drift())), f.unit().equals("s") ? "s"
                            : "tick"));
        }
        if (f.novel()) {
            b.append(String.format(Locale.ROOT, "; novel behaviour since line %d (%s)", f.novelSince(),
                    f.basis() == Forecast.Basis.VALUE_ONLY ? "no learned state fits: the value alone speaks"
                            : "matching resumed on the latest steps"));
        }
        return b.toString();
    }

    /**
     * The forecast in a few words, for a line under each pair: {@code P(violation) 0.34, about 76.0 s to the violation
     * (49.6-162 s) [matched, 10 of 29 runs]}, and {@code novel since line N} when it is.
     */
    public static String brief(Forecast f) {
        String runs = f.basis() == Forecast.Basis.VIOLATED ? ""
                : String.format(Locale.ROOT, ", %d of %d runs", f.violated(), f.runs());
        return probability(f) + ", " + time(f) + " [" + f.basis().label() + runs + "]"
                + (f.novel() ? "; novel since line " + f.novelSince() : "");
    }

    /** The whole forecast on one line. */
    public static String line(Forecast f) {
        return probability(f) + ", " + time(f) + " [" + f.basis().label() + "]: " + evidence(f);
    }

    private static String amount(double x) {
        return Math.abs(x) >= 100 ? String.format(Locale.ROOT, "%.0f", x)
                : Math.abs(x) >= 10 ? String.format(Locale.ROOT, "%.1f", x) : String.format(Locale.ROOT, "%.2f", x);
    }
}
