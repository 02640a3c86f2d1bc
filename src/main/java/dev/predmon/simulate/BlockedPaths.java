package dev.predmon.simulate;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * The blocked paths of one run ({@link Novelties#aborts()}): where a navigation is blocked, how long the robot stays
 * stuck there, and the aborts that followed. {@link Components} asks it at every {@code goTo} and every step of
 * motion.
 *
 * <p>A navigation that may be blocked is blocked at a random point between 10% and 90% of its length. The robot
 * stops there; the navigation component keeps answering RUNNING while it tries to get round (the battery drains as
 * while moving: the robot is powered and busy), then gives up with ABORT. The tree then sends {@code goTo} again and
 * the robot goes on from where it stands. A navigation that is halted, or whose battery runs out, before it aborts
 * does not count: its abort moves on to the next navigation that may be blocked.
 */
final class BlockedPaths {

    /**
     * One abort, in simulated seconds since the run's first tick.
     *
     * @param location  where the robot was heading
     * @param stuckFrom when it stopped at the blocked point
     * @param abortAt   when the navigation gave up
     */
    record Blockage(String location, double stuckFrom, double abortAt) {
    }

    private final Novelties novelties;
    private final SplittableRandom random;
    private final List<Blockage> happened = new ArrayList<>();
    private int left;
    private String target;
    private final BlockPoint block = new BlockPoint();
    /** Seconds the robot still stays stuck; NaN while it is not stuck. */
    private double stuckLeft = Double.NaN;
    private double stuckFrom;
    /** The target of the navigation a blocked path aborted last, until the next goTo: that goTo is a retry. */
    private String aborted;

    BlockedPaths(Novelties novelties, SplittableRandom random) {
        this.novelties = novelties;
        this.random = random;
        this.left = novelties.aborts();
    }

    /**
     * A navigation towards {@code location}, {@code length} metres away in a straight line, begins.
     *
     * @return whether it retries a navigation that a blocked path aborted
     */
    boolean start(String location, double length) {
        boolean retry = location.equals(aborted);
        aborted = null;
        target = location;
        stuckLeft = Double.NaN;
        block.start(left > 0 && mayBlock(location) ? length * random.nextDouble(0.1, 0.9) : Double.NaN);
        return retry;
    }

    private boolean mayBlock(String location) {
        return switch (novelties.abortOn()) {
            case DESTINATION -> location.equals(novelties.destination());
            case STATION -> location.equals(Components.CHARGING_STATION);
            case ANY -> true;
        };
    }

    /**
     * How far the robot gets of a {@code step} it tries to take at simulated time {@code time}: all of it, or up to
     * the blocked point, where it becomes {@link #stuck()}.
     */
    double step(double step, double time) {
        boolean stops = block.reaches(step);
        double allowed = block.take(step);
        if (stops) {
            stuckLeft = novelties.stuck().draw(random);
            stuckFrom = time;
        }
        return allowed;
    }

    /** Whether the robot stands at a blocked point. */
    boolean stuck() {
        return !Double.isNaN(stuckLeft);
    }

    /**
     * The robot stays stuck {@code dt} more seconds, up to simulated time {@code time}.
     *
     * @return true when the navigation gives up now: its status becomes ABORT
     */
    boolean waitOut(double dt, double time) {
        stuckLeft -= dt;
        if (stuckLeft > 1e-9) {
            return false;
        }
        stuckLeft = Double.NaN;
        left--;
        aborted = target;
        happened.add(new Blockage(target, stuckFrom, time));
        return true;
    }

    /** The navigation stops for another reason (halt, empty battery): a pending blockage is forgotten. */
    void stop() {
        stuckLeft = Double.NaN;
        block.clear();
    }

    /** The aborts so far, in order. */
    List<Blockage> happened() {
        return List.copyOf(happened);
    }
}
