package dev.predmon.simulate;

import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.List;

/**
 * What a run's messages show, read off the events the way a reader of the log would see them: the
 * {@code level} replies, where the robot was sent and where it arrived. The simulator keeps a sample only
 * if these facts tell its scenario's story.
 *
 * <p>A {@code goTo} that follows an ABORT reply for the same location is the tree retrying that navigation, not a
 * new trip: a {@code recharge} run whose way to the station was blocked still goes to the station once.
 */
record RunFacts(List<double[]> timeline, double minLevel, Double turnTime, Double turnLevel, Double violationTime,
                Double violationLevel, int goToStationCount, Double stationTime, Double stationLevel,
                boolean chargedFull, Double kitchenTime, boolean emptied, double endTime) {

    /** The level below which the safety monitor fires. */
    static final double SAFETY_BOUND = 20.0;
    /**
     * The lowest level a {@code recharge} run may reach: the thesis's premise for raising the Early Warning to
     * 50% (Section 5.2) is that a nominal robot reaches the station with margin, at most 20 points below the
     * Early Warning and never closer than 1 point to the safety bound. Without that margin a depleted run is
     * indistinguishable from a nominal late arrival until the violation itself, for any monitor.
     */
    static double rechargeMinLevel(double earlyWarning) {
        return Math.max(SAFETY_BOUND + 1.0, earlyWarning - 20.0);
    }

    static RunFacts of(List<SimEvent> events, double earlyWarning) {
        return of(events, earlyWarning, Components.KITCHEN);
    }

    /** @param destination the tour location's name ({@code kitchen} unless the run was given a new one) */
    static RunFacts of(List<SimEvent> events, double earlyWarning, String destination) {
        List<double[]> timeline = new ArrayList<>();
        double min = Double.POSITIVE_INFINITY;
        double last = Double.NaN;
        Double turnTime = null;
        Double turnLevel = null;
        Double violationTime = null;
        Double violationLevel = null;
        int goToStation = 0;
        Double stationTime = null;
        Double stationLevel = null;
        boolean full = false;
        Double kitchenTime = null;
        boolean emptied = false;
        boolean stationAborted = false;
        for (SimEvent e : events) {
            if (e.kind() == RecordKind.COMMAND && e.command().equals("goTo")
                    && e.argument().equals(Components.CHARGING_STATION)) {
                goToStation += stationAborted ? 0 : 1;
                stationAborted = false;
            }
            if (e.kind() == RecordKind.REPLY && e.command().equals("getStatus")
                    && e.argument().equals(Components.CHARGING_STATION)) {
                stationAborted = e.reply().equals(Integer.toString(Components.ABORT));
            }
            if (e.kind() != RecordKind.REPLY) {
                continue;
            }
            if (e.command().equals("level")) {
                double v = Double.parseDouble(e.reply());
                timeline.add(new double[] {e.time(), v});
                min = Math.min(min, v);
                last = v;
                if (turnTime == null && v <= earlyWarning) {
                    turnTime = e.time();
                    turnLevel = v;
                }
                if (violationTime == null && v < SAFETY_BOUND) {
                    violationTime = e.time();
                    violationLevel = v;
                }
                full |= stationTime != null && v == 100.0;
                emptied |= v == 0.0;
            } else if (e.command().equals("isAtLocation") && e.reply().equals("1")) {
                if (e.argument().equals(Components.CHARGING_STATION) && stationTime == null) {
                    stationTime = e.time();
                    stationLevel = Double.isNaN(last) ? null : last;
                } else if (e.argument().equals(destination) && kitchenTime == null) {
                    kitchenTime = e.time();
                }
            }
        }
        double end = events.isEmpty() ? 0 : events.get(events.size() - 1).time();
        return new RunFacts(timeline, min, turnTime, turnLevel, violationTime, violationLevel, goToStation,
                stationTime, stationLevel, full, kitchenTime, emptied, end);
    }

    /** Whether these facts are the story of {@code scenario} (see {@link Scenario}). */
    boolean tell(Scenario scenario, double earlyWarning) {
        return tell(scenario, earlyWarning, true, rechargeMinLevel(earlyWarning));
    }

    /**
     * Whether these facts are the story of {@code scenario} as the novelties tell it.
     *
     * @param arrives       whether a nominal run reaches the tour location (not when its way there is lost for good)
     * @param rechargeFloor the lowest level a {@code recharge} run may read
     */
    boolean tell(Scenario scenario, double earlyWarning, boolean arrives, double rechargeFloor) {
        return tell(scenario, earlyWarning, arrives, rechargeFloor, true);
    }

    /**
     * As above; {@code reachesStation} false when the way to the charging station is lost for good: a recharge run
     * then turns, never gets there and never gets to the tour location.
     */
    boolean tell(Scenario scenario, double earlyWarning, boolean arrives, double rechargeFloor,
                 boolean reachesStation) {
        if (scenario == Scenario.RECHARGE && !reachesStation) {
            return turnTime != null && goToStationCount == 1 && stationTime == null && kitchenTime == null
                    && minLevel >= rechargeFloor;
        }
        return switch (scenario) {
            case DIRECT -> (kitchenTime != null) == arrives && goToStationCount == 0 && minLevel > earlyWarning;
            case RECHARGE -> turnTime != null && goToStationCount == 1 && stationTime != null && chargedFull
                    && (arrives ? kitchenTime != null && kitchenTime > stationTime : kitchenTime == null)
                    && minLevel >= rechargeFloor;
            case DEPLETED -> turnTime != null && turnLevel >= SAFETY_BOUND && goToStationCount >= 1
                    && stationTime == null && kitchenTime == null && violationTime != null && emptied;
        };
    }
}
