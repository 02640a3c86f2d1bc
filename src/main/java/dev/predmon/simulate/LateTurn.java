package dev.predmon.simulate;

import dev.predmon.simulate.SimParameters.Point;

import java.util.SplittableRandom;

/**
 * A tree that turns to the charging station late ({@link Novelties#lateTurn()}): its {@code BatteryLevel} condition
 * keeps succeeding below the early warning until {@code delay} ticks after the first reading below the charger level,
 * as a battery skill whose reading is stale or a tree busy elsewhere would. After that turn it is the tree's usual
 * condition again.
 */
final class LateTurn {

    private final double chargerLevel;
    private final int delay;
    private int firstBelow = -1;
    private boolean turned;

    LateTurn(double chargerLevel, int delay) {
        this.chargerLevel = chargerLevel;
        this.delay = delay;
    }

    /** Whether {@code BatteryLevel} succeeds on the reading {@code level} at tick {@code tick}. */
    boolean batteryLevel(double level, double earlyWarning, int tick) {
        if (level > earlyWarning || turned) {
            return level > earlyWarning;
        }
        if (firstBelow < 0 && level < chargerLevel) {
            firstBelow = tick;
        }
        turned = firstBelow >= 0 && tick >= firstBelow + delay;
        return !turned;
    }

    /**
     * The world of a {@code recharge} run laid out again for this late turn: the tour location further away on the
     * same heading, and the charging station within reach of where the robot turns late, so that it still arrives
     * above the safety bound. Null when a turn this late leaves no room: the level at the turn would be too low, or
     * the way to it would take the robot more than 80% of the navigation deadline {@code navigationTicks} (a late
     * turn is to break the destination rule, not the navigation's deadline as well).
     */
    SimParameters relaidForRecharge(SimParameters p, int navigationTicks, SplittableRandom r) {
        double perMetre = p.drainRate() / p.speed();
        double lateLevel = chargerLevel - (delay + 1) * p.tickPeriod() * p.drainRate()
                - p.sensorPeriod() * p.drainRate();
        double lowest = RunFacts.SAFETY_BOUND + 2.0;
        double ticksToTurn = (p.startLevel() - lateLevel) / p.drainRate() / p.tickPeriod();
        if (lateLevel - 1.0 <= lowest || lateLevel >= p.startLevel() || ticksToTurn > 0.8 * navigationTicks) {
            return null;
        }
        double heading = Math.atan2(p.kitchen().y(), p.kitchen().x());
        double toLate = (p.startLevel() - lateLevel) / perMetre;
        Point turn = Simulator.polar(Point.ORIGIN, toLate, heading);
        Point kitchen = Simulator.polar(Point.ORIGIN, toLate + r.nextDouble(0.03, 0.5) * 100.0 / perMetre, heading);
        double arrival = r.nextDouble(lowest, lateLevel - 1.0);
        Point station = Simulator.polar(turn, (lateLevel - arrival) / perMetre, heading + r.nextDouble(-Math.PI, Math.PI));
        return p.relaid(kitchen, station);
    }

    /** Ticks the tree waits after the first reading below the charger level. */
    int delay() {
        return delay;
    }

    /** Whether the tree has turned late already. */
    boolean turned() {
        return turned;
    }
}
