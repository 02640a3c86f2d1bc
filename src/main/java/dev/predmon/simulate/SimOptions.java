package dev.predmon.simulate;

/**
 * How to simulate and how to print a run.
 *
 * <p>{@code earlyWarning}, {@code epoch}, {@code noise} and most {@code novelties} change the simulated events (the
 * tree's threshold, the time base, the sensor, the robot's mishaps); the other fields only change how
 * {@link LogWriter} prints them, so the same run can be written in every layout a real yarplogger export may have.
 *
 * @param earlyWarning percentage at or below which the tree sends the robot to the charging station
 * @param epoch        time stamps are Unix epoch seconds from a seeded start instead of seconds since start
 * @param rawLines     print yarp's INFO raw-bottle line before each DEBUG record
 * @param lateReplies  probability that a reply is printed after the next record(s) of other channels
 * @param vocab        print {@code isAtLocation} replies as YARP vocabs {@code 27503}/{@code 1818845542}
 * @param spaces       separate the time, level and text columns by a space instead of a tab
 * @param crlf         end lines with {@code \r\n} instead of {@code \n}
 * @param noise        standard deviation of the battery sensor's Gaussian noise, percentage points
 * @param novelties    what a real robot does that default runs never show ({@link Novelties#NONE}: nothing)
 * @param limits       the limits of the properties the truth judges ({@link PropertyLimits#DEFAULT} when null)
 */
public record SimOptions(double earlyWarning, boolean epoch, boolean rawLines, double lateReplies, boolean vocab,
                         boolean spaces, boolean crlf, double noise, Novelties novelties, PropertyLimits limits) {

    /** The thesis's final Early Warning (Section 5.2). */
    public static final double DEFAULT_EARLY_WARNING = 50.0;

    public SimOptions {
        if (!(earlyWarning > 20.0 && earlyWarning < 100.0)) {
            throw new IllegalArgumentException("early warning must be between 20 and 100 (exclusive), got "
                    + earlyWarning);
        }
        if (!(lateReplies >= 0.0 && lateReplies <= 1.0)) {
            throw new IllegalArgumentException("late-reply probability must be in [0, 1], got " + lateReplies);
        }
        if (!(noise >= 0.0 && noise <= 20.0)) {
            throw new IllegalArgumentException("sensor noise must be a standard deviation in [0, 20] points, got " + noise);
        }
        if (novelties == null) {
            novelties = Novelties.NONE;
        }
        if (limits == null) {
            limits = PropertyLimits.DEFAULT;
        }
    }

    /** Options whose truth judges the properties by the default limits. */
    public SimOptions(double earlyWarning, boolean epoch, boolean rawLines, double lateReplies, boolean vocab,
                      boolean spaces, boolean crlf, double noise, Novelties novelties) {
        this(earlyWarning, epoch, rawLines, lateReplies, vocab, spaces, crlf, noise, novelties, null);
    }

    /** Options without novelties. */
    public SimOptions(double earlyWarning, boolean epoch, boolean rawLines, double lateReplies, boolean vocab,
                      boolean spaces, boolean crlf, double noise) {
        this(earlyWarning, epoch, rawLines, lateReplies, vocab, spaces, crlf, noise, Novelties.NONE);
    }

    /** Options of a noise-free battery sensor. */
    public SimOptions(double earlyWarning, boolean epoch, boolean rawLines, double lateReplies, boolean vocab,
                      boolean spaces, boolean crlf) {
        this(earlyWarning, epoch, rawLines, lateReplies, vocab, spaces, crlf, 0.0, Novelties.NONE);
    }

    /** Early warning 50, relative times, tab columns, {@code \n}, replies in order, {@code 1}/{@code 0}. */
    public static SimOptions defaults() {
        return new SimOptions(DEFAULT_EARLY_WARNING, false, false, 0.0, false, false, false);
    }

    public SimOptions withEarlyWarning(double value) {
        return new SimOptions(value, epoch, rawLines, lateReplies, vocab, spaces, crlf, noise, novelties, limits);
    }

    public SimOptions withEpoch(boolean value) {
        return new SimOptions(earlyWarning, value, rawLines, lateReplies, vocab, spaces, crlf, noise, novelties, limits);
    }

    public SimOptions withRawLines(boolean value) {
        return new SimOptions(earlyWarning, epoch, value, lateReplies, vocab, spaces, crlf, noise, novelties, limits);
    }

    public SimOptions withLateReplies(double value) {
        return new SimOptions(earlyWarning, epoch, rawLines, value, vocab, spaces, crlf, noise, novelties, limits);
    }

    public SimOptions withVocab(boolean value) {
        return new SimOptions(earlyWarning, epoch, rawLines, lateReplies, value, spaces, crlf, noise, novelties, limits);
    }

    public SimOptions withSpaces(boolean value) {
        return new SimOptions(earlyWarning, epoch, rawLines, lateReplies, vocab, value, crlf, noise, novelties, limits);
    }

    public SimOptions withCrlf(boolean value) {
        return new SimOptions(earlyWarning, epoch, rawLines, lateReplies, vocab, spaces, value, noise, novelties, limits);
    }

    /**
     * Gaussian noise of this standard deviation, in percentage points, on every battery reading: a real sensor is
     * not monotone. The tree reacts to the noisy reading, as a real one would.
     */
    public SimOptions withNoise(double value) {
        return new SimOptions(earlyWarning, epoch, rawLines, lateReplies, vocab, spaces, crlf, value, novelties, limits);
    }

    /** The same options with these novelties (see {@link Novelties}). */
    public SimOptions withNovelties(Novelties value) {
        return new SimOptions(earlyWarning, epoch, rawLines, lateReplies, vocab, spaces, crlf, noise, value, limits);
    }

    /** The same options with these property limits (see {@link PropertyLimits}). */
    public SimOptions withLimits(PropertyLimits value) {
        return new SimOptions(earlyWarning, epoch, rawLines, lateReplies, vocab, spaces, crlf, noise, novelties, value);
    }
}
