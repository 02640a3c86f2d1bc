package dev.predmon.simulate;

/**
 * Where the way of the current navigation is blocked, and how far along it the robot has come: the part of each step
 * of motion it can take. {@link BlockedPaths} and {@link LostWay} place the point; this class stops the robot there.
 */
final class BlockPoint {

    /** Distance along the navigation where the way is blocked; NaN when it is not (or no longer). */
    private double at = Double.NaN;
    private double travelled;

    /** A navigation begins, blocked {@code at} metres along (NaN: not blocked). */
    void start(double at) {
        this.at = at;
        travelled = 0;
    }

    /** The block is forgotten: the robot no longer heads for it. */
    void clear() {
        at = Double.NaN;
    }

    /** Whether a step of {@code step} metres gets to the blocked point. */
    boolean reaches(double step) {
        return !Double.isNaN(at) && travelled + step >= at;
    }

    /** Takes the step, or the part of it up to the blocked point, where the robot stops (the point is then passed). */
    double take(double step) {
        if (!reaches(step)) {
            travelled += step;
            return step;
        }
        double allowed = at - travelled;
        travelled = at;
        at = Double.NaN;
        return allowed;
    }
}
