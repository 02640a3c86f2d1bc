package dev.predmon.property;

/**
 * A property's verdict on a run so far. Every kind is a safety property: {@link Violated} is final; {@link Holds}
 * and {@link Pending} are verdicts on a prefix, which is all a monitor of an unfinished run, or of a log that
 * stopped, has. {@link NoEvidence} is no verdict: nothing the property speaks of occurred in the run (yet), so that
 * "holds" would be said of nothing.
 */
public sealed interface Verdict permits Verdict.Holds, Verdict.Pending, Verdict.Violated, Verdict.NoEvidence {

    /**
     * {@code holds}, {@code pending}, {@code violated} or {@code no-evidence}: the verdict's name in events and
     * summaries.
     */
    String id();

    /** The verdict in a user's words. */
    String describe();

    /** Nothing violated the property so far (nothing is owed either). */
    Holds HOLDS = new Holds();

    /** Nothing violated the property so far and nothing is owed. */
    record Holds() implements Verdict {
        @Override
        public String id() {
            return "holds";
        }

        @Override
        public String describe() {
            return "holds";
        }
    }

    /**
     * A bounded response is owed: its trigger came, its deadline has not passed yet. At the end of a log, the
     * deadline was not due: neither held nor violated.
     *
     * @param line     the trigger's line
     * @param since    when it came, in {@code unit}: the run's tick count, the log's time, or 1 for the first occurrence
     * @param deadline the last moment, in {@code unit}, at which the response is in time
     * @param unit     what {@code since} and {@code deadline} count
     */
    record Pending(long line, double since, double deadline, Deadline.Unit unit) implements Verdict {
        @Override
        public String id() {
            return "pending";
        }

        @Override
        public String describe() {
            String due = switch (unit) {
                case TICKS -> "tick " + Numbers.text(since) + " of the run, due by tick " + Numbers.text(deadline);
                case SECONDS -> "t=" + Numbers.text(since) + ", due by t=" + Numbers.text(deadline);
                case OCCURRENCES -> "occurrence " + Numbers.text(since) + ", due by occurrence "
                        + Numbers.text(deadline);
            };
            return "pending since line " + line + " (" + due + ")";
        }
    }

    /**
     * The property was violated.
     *
     * @param line   the line of the record that violated it (the event, the reading, the record past the deadline)
     * @param time   that record's time
     * @param value  the violating value of a bound, or null
     * @param before the reading before it on the same channel, or null
     * @param what   what happened, in words ({@code GoTo/getStatus reply 3}; {@code 18.5 below the floor 20})
     */
    record Violated(long line, double time, Double value, Double before, String what) implements Verdict {
        @Override
        public String id() {
            return "violated";
        }

        @Override
        public String describe() {
            return "violated at line " + line + ": " + what;
        }
    }

    /**
     * Nothing the property speaks of occurred in the run so far: a bound's value was never read, an absence's or a
     * precedence's message never came, a response was never triggered, or its scope never opened. Neither held nor
     * violated, and never green: a misspelt name gives this on every run.
     *
     * @param why what never occurred, in words ({@code no reading of BatteryReader/levle})
     */
    record NoEvidence(String why) implements Verdict {
        @Override
        public String id() {
            return "no-evidence";
        }

        @Override
        public String describe() {
            return "no evidence (" + why + ")";
        }
    }
}
