package dev.predmon.simulate;

/**
 * The physical parameters of one run, sampled from the seed (see {@link Simulator} for the ranges).
 *
 * @param attempt        how many samples were rejected before this one told the scenario's story
 * @param tickPeriod     seconds between two ticks of the tree
 * @param speed          robot speed in m/s
 * @param drainRate      battery percentage lost per second while moving
 * @param idleDrainRate  percentage lost per second while standing still
 * @param drainNoise     relative amplitude of the per-tick drain noise (0.1 = +-10%)
 * @param chargeRate     percentage gained per second while charging
 * @param sensorPeriod   seconds between two readings of the battery sensor ({@code level} repeats its last one)
 * @param startLevel     battery percentage at the start
 * @param tolerance      metres within which {@code isAtLocation} answers true
 * @param kitchen        position of the destination, metres (the robot starts at the origin)
 * @param chargingStation position of the charging station, metres
 * @param goToEchoesDestination whether the {@code goTo} reply prints the destination (else it is empty)
 * @param startTime      log time of the first record, seconds
 * @param tailTicks      ticks run after the tree succeeds or after the robot stops
 */
public record SimParameters(int attempt, double tickPeriod, double speed, double drainRate, double idleDrainRate,
                            double drainNoise, double chargeRate, double sensorPeriod, double startLevel,
                            double tolerance, Point kitchen, Point chargingStation, boolean goToEchoesDestination,
                            double startTime, int tailTicks) {

    /**
     * The same run with a robot {@code slowdown} times slower and a battery that drains {@code drainFactor} times
     * faster (moving and idle), in the same world: the geometry was placed for the sampled robot, so the novelty
     * shows in where the battery stands when the robot arrives.
     */
    SimParameters slowed(double slowdown, double drainFactor) {
        return new SimParameters(attempt, tickPeriod, speed / slowdown, drainRate * drainFactor,
                idleDrainRate * drainFactor, drainNoise, chargeRate, sensorPeriod, startLevel, tolerance, kitchen,
                chargingStation, goToEchoesDestination, startTime, tailTicks);
    }

    /** The same run with ticks of the tree {@code seconds} apart (the sensor keeps its period). */
    SimParameters withTickPeriod(double seconds) {
        return new SimParameters(attempt, seconds, speed, drainRate, idleDrainRate, drainNoise, chargeRate, sensorPeriod,
                startLevel, tolerance, kitchen, chargingStation, goToEchoesDestination, startTime, tailTicks);
    }

    /** The same run in a world with the tour location and the charging station elsewhere. */
    SimParameters relaid(Point tourLocation, Point station) {
        return new SimParameters(attempt, tickPeriod, speed, drainRate, idleDrainRate, drainNoise, chargeRate,
                sensorPeriod, startLevel, tolerance, tourLocation, station, goToEchoesDestination, startTime,
                tailTicks);
    }

    /** A 2D position in metres. */
    public record Point(double x, double y) {
        public static final Point ORIGIN = new Point(0, 0);

        public double distance(Point other) {
            return Math.hypot(other.x - x, other.y - y);
        }
    }
}
