package dev.predmon.property;

/**
 * How long a bounded response may take: {@code amount} ticks of the tree, seconds of the log's time, or occurrences
 * of a retry event ({@code closeHand} attempts).
 *
 * @param amount  the most that may pass: the response must come before more than this has passed
 * @param unit    what {@code amount} counts
 * @param counted for {@link Unit#OCCURRENCES}, the event counted (the trigger counts when it is one); else null
 */
public record Deadline(double amount, Unit unit, Event counted) {

    /** What a deadline counts. */
    public enum Unit {
        /**
         * {@code Tick} records of the tree since the trigger. In a log without time stamps a record's time is the
         * tick number, so ticks are also its clock.
         */
        TICKS("ticks"),
        /**
         * Seconds of the log's time stamps since the trigger. In a log without time stamps times are tick numbers,
         * so there a second is a tick (the R1 tree ticks about once a second).
         */
        SECONDS("seconds"),
        /** Occurrences of the counted event since the trigger, the trigger included when it is one. */
        OCCURRENCES("occurrences");

        /** The key of the abstraction file, and the unit in words. */
        public final String key;

        Unit(String key) {
            this.key = key;
        }
    }

    public Deadline {
        if (!(amount >= 0) || Double.isInfinite(amount)) {
            throw new IllegalArgumentException("a deadline is a finite amount >= 0, got " + amount);
        }
        if ((unit == Unit.OCCURRENCES) != (counted != null)) {
            throw new IllegalArgumentException("an event is counted exactly when the deadline counts occurrences");
        }
    }

    /** In a user's words: {@code 10 ticks}, {@code 8 occurrences of ArmService/closeHand command}. */
    public String describe() {
        return Numbers.text(amount) + " " + (unit == Unit.OCCURRENCES ? "occurrences of " + counted.describe()
                : unit.key);
    }
}
