package dev.predmon.simulate;

import java.util.SplittableRandom;

/**
 * A navigation that never arrives ({@link Novelties#neverArrives()}): the way to the tour location (or to the charging
 * station, {@link Novelties#lostWay()}) is blocked at a
 * random point between 10% and 90% of its length, and the robot waits there for good. The navigation component goes
 * on answering RUNNING, the robot stands (its battery drains at the idle rate), and the capture stops a number of
 * ticks later. A navigation that is halted is not blocked any more: the next one to the tour location is.
 */
final class LostWay {

    private final String destination;
    private final int ticks;
    private final SplittableRandom random;
    private final BlockPoint block = new BlockPoint();
    private int stuckTicks = -1;
    private double stuckFrom = Double.NaN;

    /** @param ticks ticks the capture goes on once the robot is stuck */
    LostWay(String destination, int ticks, SplittableRandom random) {
        this.destination = destination;
        this.ticks = ticks;
        this.random = random;
    }

    /** A navigation towards {@code location}, {@code length} metres away, begins. */
    void start(String location, double length) {
        block.start(!stuck() && location.equals(destination) ? length * random.nextDouble(0.1, 0.9) : Double.NaN);
    }

    /** How far the robot gets of a {@code step} at simulated time {@code time}: up to the blocked point. */
    double step(double step, double time) {
        if (block.reaches(step)) {
            stuckTicks = 0;
            stuckFrom = time;
        }
        return block.take(step);
    }

    /** Whether the way lost is the one to the charging station. */
    boolean toStation() {
        return destination.equals(Components.CHARGING_STATION);
    }

    /** Whether the robot waits at the blocked point. */
    boolean stuck() {
        return stuckTicks >= 0;
    }

    /** One more tick of waiting. */
    void waited() {
        stuckTicks++;
    }

    /** Whether the capture stops: the robot has waited its ticks. */
    boolean captureOver() {
        return stuckTicks >= ticks;
    }

    /** Simulated seconds since the first tick when the robot stopped for good, NaN before. */
    double stuckFrom() {
        return stuckFrom;
    }

    /** The navigation is halted: the robot no longer heads for the blocked point, or waits at it. */
    void stop() {
        block.clear();
        stuckTicks = -1;
    }
}
