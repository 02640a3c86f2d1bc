package dev.predmon.simulate;

import dev.predmon.simulate.Ledger.Note;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Judges the properties of the R1 system on a run, from the simulator's {@link Ledger}: what the tree read and sent
 * and what the components did, tick by tick. The semantics, per property id:
 *
 * <ul>
 *   <li>{@code battery}: every {@code level} reading is at least the floor; violated at the first one below.
 *   <li>{@code charger-in-time} (SCOPE's destination rule): while the last reading is below the charger level and the
 *       last {@code goTo} was not to {@code charging_station}, the obligation is pending; a {@code goTo} to the
 *       station or a reading at or above the level ends it. Violated when a tick begins with it pending for the
 *       allowed ticks ({@code pending since tick t}, violated at the Tick {@code t + 10}).
 *   <li>{@code no-abort}: no {@code getStatus} reply is 3 (ABORT); violated at the first one, whatever its cause.
 *   <li>{@code navigation-in-time}: a trip begins with a {@code goTo} to a place other than the current trip's (a
 *       {@code goTo} to the same place after an abort retries the trip) and ends when the robot reaches the place
 *       (discharged) or the tree halts it (cancelled). Violated when a tick begins with a trip that began the
 *       allowed ticks earlier still open.
 *   <li>{@code grasp-in-time}: each grasp attempt is a {@code closeHand} and the {@code hasGrasped} reply after it;
 *       violated at the reply of the attempt that fails with the allowed attempts used up.
 * </ul>
 * A deadline that the run ends before is not a violation: the truth says what the log shows.
 */
final class PropertyJudge {

    static final String BATTERY = "battery";
    static final String CHARGER_IN_TIME = "charger-in-time";
    static final String NO_ABORT = "no-abort";
    static final String NAVIGATION_IN_TIME = "navigation-in-time";
    static final String GRASP_IN_TIME = "grasp-in-time";

    /** The properties in the order the truth lists them. */
    static final List<String> IDS = List.of(BATTERY, CHARGER_IN_TIME, NO_ABORT, NAVIGATION_IN_TIME, GRASP_IN_TIME);

    /**
     * Where a property was first violated.
     *
     * @param event index of the record in the run's events
     * @param tick  the tick of the tree
     */
    record Violation(int event, int tick) {
    }

    private PropertyJudge() {
    }

    /** The first violation of each property violated, by property id. */
    static Map<String, Violation> judge(Ledger ledger, PropertyLimits limits) {
        Map<String, Violation> first = new LinkedHashMap<>();
        double level = Double.NaN;
        String destination = null;
        int chargerSince = -1;
        String trip = null;
        int tripSince = -1;
        int attempts = 0;
        for (Note n : ledger.notes()) {
            switch (n.kind()) {
                case TICK -> {
                    if (chargerSince >= 0 && n.tick() >= chargerSince + limits.chargerTicks()) {
                        first.putIfAbsent(CHARGER_IN_TIME, at(n));
                    }
                    if (trip != null && n.tick() >= tripSince + limits.navigationTicks()) {
                        first.putIfAbsent(NAVIGATION_IN_TIME, at(n));
                    }
                }
                case READING -> {
                    level = n.value();
                    if (level < limits.batteryFloor()) {
                        first.putIfAbsent(BATTERY, at(n));
                    }
                }
                case GO_TO -> {
                    destination = n.place();
                    if (!n.place().equals(trip)) {
                        trip = n.place();
                        tripSince = n.tick();
                    }
                }
                case HALT, ARRIVAL -> {
                    if (n.place().equals(trip)) {
                        trip = null;
                    }
                }
                case STATUS -> {
                    if (n.value() == Components.ABORT) {
                        first.putIfAbsent(NO_ABORT, at(n));
                    }
                }
                case GRASP -> {
                    attempts = n.value() == 1 ? 0 : attempts + 1;
                    if (attempts == limits.graspAttempts()) {
                        first.putIfAbsent(GRASP_IN_TIME, at(n));
                    }
                }
                default -> throw new IllegalStateException(n.kind().toString());
            }
            if (n.kind() == Ledger.Kind.READING || n.kind() == Ledger.Kind.GO_TO) {
                boolean pending = level < limits.chargerLevel() && !Components.CHARGING_STATION.equals(destination);
                chargerSince = !pending ? -1 : chargerSince >= 0 ? chargerSince : n.tick();
            }
        }
        return first;
    }

    private static Violation at(Note n) {
        return new Violation(n.event(), n.tick());
    }
}
