package dev.predmon.parse;

/**
 * What a record's {@link LogRecord#time() time} counts. yarplogger's layouts stamp every entry with seconds
 * (relative or epoch); the monitor's console output has no time stamps at all, and there the run's clock is the
 * tree's tick: the number of the last {@code Tick} record.
 */
public enum Clock {
    /** Seconds, relative to the run or since the Unix epoch, as the log has them. */
    SECONDS("s"),
    /** The behavior tree's tick number (1 at the start of a run, about one a second). */
    TICKS("ticks");

    private final String unit;

    Clock(String unit) {
        this.unit = unit;
    }

    /** The unit as printed after a figure: {@code s} or {@code ticks}. */
    public String unit() {
        return unit;
    }
}
