package dev.predmon.abstraction;

/**
 * Where one run of the robot ends and the next begins, in a log that holds several (the monitor keeps printing
 * across missions, so a robot's day is one log).
 *
 * @param tickRestart a {@code Tick} record whose number is not above the previous tick's starts a run: the tree's
 *                    tick counter starts again at 1 with every run
 * @param silence     seconds without any record after which the next record starts a run (logs with time stamps;
 *                    0: off); the tree ticks about once a second and reads its battery every few, so a long silence
 *                    means it stopped
 */
public record RunRule(boolean tickRestart, double silence) {

    /** Half a minute: far longer than any pause of a ticking tree, far shorter than a robot's rest between missions. */
    public static final double DEFAULT_SILENCE = 30.0;

    /** The rule of a file that does not say: both, with the default silence. */
    public static final RunRule DEFAULT = new RunRule(true, DEFAULT_SILENCE);
}
