package dev.predmon.simulate;

/**
 * The limits of the properties that a run's truth judges (see {@link PropertyTruth}): the simulator's own reading of
 * them, kept apart from the property monitor so that the two can check each other.
 *
 * @param batteryFloor       {@code battery}: every {@code level} reading is at least this
 * @param chargerLevel       {@code charger-in-time}: a reading below this obliges the tree to head for the charging
 *                           station
 * @param chargerTicks       {@code charger-in-time}: ticks the tree has to send {@code goTo(charging_station)}
 * @param navigationTicks    {@code navigation-in-time}: ticks a navigation has, from its first {@code goTo}, to
 *                           reach its destination
 * @param graspAttempts      {@code grasp-in-time}: {@code closeHand} attempts a grasp has to succeed
 */
public record PropertyLimits(double batteryFloor, double chargerLevel, int chargerTicks, int navigationTicks,
                             int graspAttempts) {

    /**
     * The built-in abstractions' limits, so that a simulated run's truth and the safety monitor judge the same
     * property: SCOPE's battery and destination rules (20, below 30 within 10 ticks); a navigation deadline of 400
     * ticks, half as long again as the recordings' longest navigation (268); a grasp within 8 attempts, twice the
     * recordings' most (4).
     */
    public static final PropertyLimits DEFAULT = new PropertyLimits(20.0, 30.0, 10, 400, 8);

    public PropertyLimits {
        if (!(batteryFloor >= 0 && batteryFloor < chargerLevel && chargerLevel <= 100)) {
            throw new IllegalArgumentException("expected 0 <= battery floor < charger level <= 100, got "
                    + batteryFloor + " and " + chargerLevel);
        }
        if (chargerTicks < 1 || navigationTicks < 1 || graspAttempts < 1) {
            throw new IllegalArgumentException("the charger and navigation deadlines and the grasp attempts must be "
                    + "at least 1, got " + chargerTicks + ", " + navigationTicks + " and " + graspAttempts);
        }
    }

    /** The same limits with a navigation deadline of {@code ticks}. */
    public PropertyLimits withNavigationTicks(int ticks) {
        return new PropertyLimits(batteryFloor, chargerLevel, chargerTicks, ticks, graspAttempts);
    }

    /** The same limits with {@code attempts} grasp attempts. */
    public PropertyLimits withGraspAttempts(int attempts) {
        return new PropertyLimits(batteryFloor, chargerLevel, chargerTicks, navigationTicks, attempts);
    }
}
