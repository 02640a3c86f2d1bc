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
 * @param quiet       seconds without any record after which the tree starting over begins a run: the first command of
 *                    the skill-component interface after such a pause is the command the log began with (logs with
 *                    time stamps; 0: off). Runs separated by a few seconds, in a log without ticks, split this way;
 *                    a pause of a running tree does not, because it goes on with other commands
 */
public record RunRule(boolean tickRestart, double silence, double quiet) {

    /**
     * Three seconds: three ticks of a tree that ticks about once a second, shorter than the pause between two missions
     * of a robot that starts the next at once.
     */
    public static final double DEFAULT_QUIET = 3.0;

    /** A rule with the default quiet pause. */
    public RunRule(boolean tickRestart, double silence) {
        this(tickRestart, silence, silence > 0 ? Math.min(DEFAULT_QUIET, silence) : 0.0);
    }

    /** Half a minute: far longer than any pause of a ticking tree, far shorter than a robot's rest between missions. */
    public static final double DEFAULT_SILENCE = 30.0;

    /** The rule of a file that does not say: both, with the default silence. */
    public static final RunRule DEFAULT = new RunRule(true, DEFAULT_SILENCE);
}
