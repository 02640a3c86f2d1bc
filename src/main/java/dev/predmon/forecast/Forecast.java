package dev.predmon.forecast;

/**
 * How likely the run is to violate the safety property, and how soon, after one compacted pair.
 *
 * @param probability     P(this run violates the property), 0 to 1
 * @param timeToViolation if it does, the estimated time until it does, in the log's unit; null when no violation is
 *                        in sight (the property is not falling and no training run from here violated)
 * @param low             the short end of that estimate's interval, or null
 * @param high            the long end, or null when it is open (the property may stop falling)
 * @param basis           what the forecast rests on
 * @param novelSince      the line from which the run did something no learned machine does, or null
 * @param runs            training runs behind the estimate (through the current states, or at this value)
 * @param violated        how many of them violated
 * @param value           the property's current value, or null before the first reading
 * @param drift           the property's rate of change per unit of time used for the time, or null
 * @param unit            what the times count: {@code s} or {@code ticks}
 */
public record Forecast(double probability, Double timeToViolation, Double low, Double high, Basis basis,
                       Long novelSince, int runs, int violated, Double value, Double drift, String unit) {

    /** What a forecast rests on, from the most to the least informed. */
    public enum Basis {
        /** The run matches learned machines exactly: their states' statistics. */
        MATCHED("matched"),
        /** The run did something new, and matching resumed on the latest pairs: weaker evidence. */
        RESYNCHRONISED("resynchronised"),
        /** Nothing learned matches the latest pairs: the property's value and drift alone. */
        VALUE_ONLY("value only"),
        /**
         * Nothing learned matches the latest pairs, and the property has no value (an absence, a precedence): how
         * often the training runs violated it.
         */
        BASE_RATE("base rate"),
        /** The property has already been violated in this run. */
        VIOLATED("violated");

        private final String label;

        Basis(String label) {
            this.label = label;
        }

        /** As shown to users and in JSON. */
        public String label() {
            return label;
        }
    }

    public Forecast {
        if (!(probability >= 0.0 && probability <= 1.0)) {
            throw new IllegalArgumentException("probability out of [0, 1]: " + probability);
        }
    }

    /** Whether the run has done something no learned machine does (the forecast is then less informed). */
    public boolean novel() {
        return novelSince != null;
    }
}
