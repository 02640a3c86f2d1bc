package dev.predmon.simulate;

import java.util.SplittableRandom;

/**
 * The novelties of one attempt at a run that act while it is simulated, each drawn from the run's novelty stream:
 * the blocked paths, the way to the tour location lost for good, the late turn and the arm. Each is null when its
 * option was not given, so that the run takes the steps it always took.
 *
 * @param blocked  the blocked paths that abort, or null
 * @param lost     the way to the tour location lost for good, or null
 * @param lateTurn the tree's late turn to the charger, or null
 * @param arm      the arm of a grasp at the tour location, or null
 */
record Mishaps(BlockedPaths blocked, LostWay lost, LateTurn lateTurn, Arm arm) {

    /** Draws the novelties that {@code novelties} ask for from {@code novel} (null when no novelty changes runs). */
    static Mishaps draw(Novelties novelties, PropertyLimits limits, SplittableRandom novel, BlockedPaths blocked) {
        LostWay lost = novelties.neverArrives() == null ? null : new LostWay(novelties.lostWay(),
                ticks(novelties.neverArrives().draw(novel)), novel.split());
        Arm arm = !novelties.grasp() ? null : new Arm(novelties.graspFailures() == null ? novel.nextInt(0, 4)
                : ticks(novelties.graspFailures().draw(novel)));
        LateTurn late = novelties.lateTurn() == null ? null
                : new LateTurn(limits.chargerLevel(), ticks(novelties.lateTurn().draw(novel)));
        return new Mishaps(blocked, lost, late, arm);
    }

    private static int ticks(double drawn) {
        return (int) Math.round(drawn);
    }

    /**
     * Whether a run of {@code scenario} must end stuck for good: a depleted run never reaches the tour location (nor
     * the station), and only a recharge run goes to the charging station.
     */
    boolean stuckForGood(Scenario scenario) {
        return lost != null && scenario != Scenario.DEPLETED
                && (!lost.toStation() || scenario == Scenario.RECHARGE);
    }

    /** Whether a run that heads for the charging station gets there (its way there is not lost for good). */
    boolean reachesStation() {
        return lost == null || !lost.toStation();
    }

    /** Whether a run's story ends at the tour location. */
    boolean arrives(Scenario scenario) {
        return !stuckForGood(scenario);
    }

    /** Whether the run that was simulated is the one its scenario needs with these novelties. */
    boolean kept(Scenario scenario) {
        return lost == null || lost.captureOver() == stuckForGood(scenario);
    }

    /**
     * The lowest level a {@code recharge} run may read: the scenario's margin, or the safety bound for a tree that
     * turns late (it turns below the charger level, so no margin is left; the run still never falls below 20).
     */
    double rechargeFloor(double earlyWarning) {
        return lateTurn == null ? RunFacts.rechargeMinLevel(earlyWarning) : RunFacts.SAFETY_BOUND;
    }

    /** Log time when the robot stopped for good, or null; {@code t0} is the log time of the run's first tick. */
    Double stuckForGood(double t0) {
        return lost == null || !lost.captureOver() ? null : Math.round((t0 + lost.stuckFrom()) * 1e6) / 1e6;
    }

    /** The grasp attempts made, or null without a grasp. */
    Integer graspAttempts() {
        return arm == null ? null : arm.attempts();
    }

    /** The ticks of the late turn, or null when the tree did not turn late. */
    Integer lateTurnTicks() {
        return lateTurn == null || !lateTurn.turned() ? null : lateTurn.delay();
    }
}
