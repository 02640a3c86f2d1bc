package dev.predmon.simulate;

import dev.predmon.simulate.SimParameters.Point;

import java.util.Map;
import java.util.SplittableRandom;

/**
 * The two components of the case study (thesis Section 3.2.3) and the physics that links them: the robot
 * drains the battery while it moves, and charges it when it stops at the charging station.
 *
 * <p>The world only changes between ticks ({@link #advance}); within a tick every call sees the same state,
 * which is what a tick period much longer than an RPC round trip gives on the real robot.
 *
 * <p>The tour location is the {@code kitchen} unless a run is given a new one; a run with blocked paths
 * ({@link BlockedPaths}) has navigations that stop short and abort.
 */
final class Components {

    static final String KITCHEN = "kitchen";
    static final String CHARGING_STATION = "charging_station";

    static final int NOT_STARTED = 0;
    static final int RUNNING = 1;
    static final int SUCCESS = 2;
    static final int ABORT = 3;

    private final SimParameters p;
    private final Map<String, Point> locations;
    private final SplittableRandom noise;
    private final int stopDelayTicks;
    /** The battery sensor's noise: its own stream, so that a noise-free run draws exactly as before. */
    private final double sensorNoise;
    private final SplittableRandom sensor;
    /** Null without blocked paths, so that a default run takes the very same steps. */
    private final BlockedPaths blocked;
    /** Null unless the way to the tour location is lost for good. */
    private final LostWay lost;
    private final Ledger ledger;
    private int tick;

    private double time;
    private double level;
    private double reportedLevel;
    private double lastSample;
    private boolean charging;
    private Point position = Point.ORIGIN;
    private String target;
    private int status = NOT_STARTED;
    private int ticksSinceEmpty = -1;
    private boolean stoppedEmpty;
    private int goToStationCount;

    Components(SimParameters p, SplittableRandom noise) {
        this(p, noise, 0.0, null);
    }

    /** @param sensorNoise standard deviation of the battery sensor's Gaussian noise, drawn from {@code sensor} */
    Components(SimParameters p, SplittableRandom noise, double sensorNoise, SplittableRandom sensor) {
        this(p, noise, sensorNoise, sensor, KITCHEN, null);
    }

    /**
     * @param destination the tour location's name, at {@link SimParameters#kitchen()}
     * @param blocked     the run's blocked paths, or null for none
     */
    Components(SimParameters p, SplittableRandom noise, double sensorNoise, SplittableRandom sensor,
               String destination, BlockedPaths blocked) {
        this(p, noise, sensorNoise, sensor, destination, blocked, null, new Ledger());
    }

    /**
     * @param lost   the way to the tour location lost for good, or null
     * @param ledger where arrivals are noted
     */
    Components(SimParameters p, SplittableRandom noise, double sensorNoise, SplittableRandom sensor,
               String destination, BlockedPaths blocked, LostWay lost, Ledger ledger) {
        this.p = p;
        this.noise = noise;
        this.sensorNoise = sensorNoise;
        this.sensor = sensor;
        this.blocked = blocked;
        this.lost = lost;
        this.ledger = ledger;
        this.locations = Map.of(destination, p.kitchen(), CHARGING_STATION, p.chargingStation(), "start",
                Point.ORIGIN);
        this.stopDelayTicks = noise.nextInt(1, 4);
        this.level = p.startLevel();
        this.reportedLevel = level;
    }

    /** Moves the world on by {@code dt} seconds: motion, drain, charge and the battery sensor. */
    void advance(double dt) {
        time += dt;
        tick++;
        if (status == RUNNING && lost != null && lost.stuck()) {
            // Waiting for good at the blocked point: the navigation runs on, the robot stands.
            lost.waited();
            level -= p.idleDrainRate() * dt;
        } else if (status == RUNNING) {
            if (blocked != null && blocked.stuck()) {
                // Stuck at a blocked point: no progress, the same drain, until the navigation gives up.
                if (blocked.waitOut(dt, time)) {
                    status = ABORT;
                }
            } else {
                move(dt);
            }
            level -= p.drainRate() * dt * (1 + p.drainNoise() * (2 * noise.nextDouble() - 1));
        } else if (charging) {
            level += p.chargeRate() * dt * (1 + p.drainNoise() * (2 * noise.nextDouble() - 1));
            if (level >= 100.0) {
                level = 100.0;
                charging = false;
                sample();
            }
        } else {
            level -= p.idleDrainRate() * dt;
        }
        if (level <= 0.0) {
            level = 0.0;
            if (ticksSinceEmpty < 0) {
                // The battery driver reports an empty battery at once; the robot coasts a little longer.
                ticksSinceEmpty = 0;
                sample();
            } else if (++ticksSinceEmpty >= stopDelayTicks && status == RUNNING) {
                status = ABORT;
                stoppedEmpty = true;
                if (blocked != null) {
                    blocked.stop();
                }
            }
        }
        if (time - lastSample >= p.sensorPeriod() - 1e-9) {
            sample();
        }
    }

    private void move(double dt) {
        Point goal = locations.get(target);
        double remaining = position.distance(goal);
        double step = p.speed() * dt;
        if (blocked != null) {
            step = blocked.step(step, time);
        }
        if (lost != null) {
            step = lost.step(step, time);
        }
        if (step >= remaining) {
            position = goal;
            status = SUCCESS;
            ledger.arrived(target, tick);
            if (CHARGING_STATION.equals(target) && level < 100.0) {
                charging = true;
            }
        } else {
            double f = step / remaining;
            position = new Point(position.x() + f * (goal.x() - position.x()),
                    position.y() + f * (goal.y() - position.y()));
        }
    }

    private void sample() {
        reportedLevel = sensorNoise > 0 ? Math.min(100.0, Math.max(0.0, level + sensorNoise * gaussian())) : level;
        lastSample = time;
    }

    /** A standard normal draw (Box-Muller; SplittableRandom has no nextGaussian in Java 17). */
    private double gaussian() {
        double u = 1.0 - sensor.nextDouble();
        return Math.sqrt(-2.0 * Math.log(u)) * Math.cos(2 * Math.PI * sensor.nextDouble());
    }

    /** {@code BatteryReader.level()}: the last sensor reading, a percentage. */
    double level() {
        return reportedLevel;
    }

    /** {@code BatteryReader.charging_status()}: 1 while charging, else 0. */
    int chargingStatus() {
        return charging ? 1 : 0;
    }

    /** {@code GoTo.goTo(destination)}: starts moving there, unless the battery is empty. */
    void goTo(String destination) {
        target = destination;
        status = level > 0.0 ? RUNNING : ABORT;
        // The tree's retry after a blocked path is the same trip to the station, not a second one.
        boolean retry = blocked != null && blocked.start(destination, position.distance(locations.get(destination)));
        if (lost != null) {
            lost.start(destination, position.distance(locations.get(destination)));
        }
        if (CHARGING_STATION.equals(destination) && !retry) {
            goToStationCount++;
        }
        charging = false;
    }

    /** {@code GoTo.getStatus(destination)}: the navigation status if it is the current target, else NOT_STARTED. */
    int getStatus(String destination) {
        return destination.equals(target) ? status : NOT_STARTED;
    }

    /** {@code GoTo.halt(destination)}: stops the robot if it is heading there. */
    void halt(String destination) {
        if (destination.equals(target) && status == RUNNING) {
            status = ABORT;
            if (blocked != null) {
                blocked.stop();
            }
            if (lost != null) {
                lost.stop();
            }
        }
    }

    /** {@code GoTo.isAtLocation(destination)}: within the tolerance of it. */
    boolean isAtLocation(String destination) {
        return position.distance(locations.get(destination)) <= p.tolerance();
    }

    /** How often the robot was sent to the charging station. */
    int goToStationCount() {
        return goToStationCount;
    }

    /** The tick of the tree the world is in: how often it {@link #advance advanced}. */
    int tick() {
        return tick;
    }

    /** Whether the robot has stopped because the battery ran out. */
    boolean stoppedEmpty() {
        return stoppedEmpty;
    }
}
