package dev.predmon.simulate;

import java.util.Locale;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.regex.Pattern;

/**
 * What a real robot does that the default simulated runs never show: a navigation that aborts on a blocked path or
 * never arrives, a grasp that keeps failing, a late turn to the charger, a slower robot or a faster-draining battery,
 * another tick rate, a tour location no model has seen, and logs that hold several runs without Tick records. {@link #NONE} leaves every run and every log exactly as without it.
 *
 * <p>Every run still tells its scenario's story: a {@code recharge} run that was stuck on its way to the charging
 * station still arrives there at the scenario's margin, a {@code depleted} run still runs out before it. When a
 * novelty would change the outcome, the simulator draws another sample (see {@link Simulator}), so the scenario
 * stays a truthful label for evaluation.
 *
 * @param aborts      blocked-path aborts per run: the robot is stuck for {@code stuck} seconds, the navigation
 *                    component then answers {@code getStatus} with ABORT (3) and the tree sends {@code goTo} again
 * @param abortOn     which navigations may be blocked
 * @param stuck       seconds the robot stays stuck before the navigation aborts, drawn per abort
 * @param slowdown    the robot's speed is divided by this factor, drawn per run (1 = as sampled)
 * @param drainFactor the battery's drain rates (moving and idle) are multiplied by this factor, drawn per run
 * @param newLocation the tour destination's name instead of {@code kitchen}, or null
 * @param noTicks     the log leaves out the Tick records
 * @param gap         seconds of silence between two runs of one log, drawn per gap; null for the default 5 s
 * @param neverArrives ticks the log goes on after the robot got stuck for good on its way to the tour location
 *                    (the navigation answers RUNNING until the capture stops), drawn per run; null for none
 * @param grasp       whether the robot grasps an object at the tour location (closeHand, hasGrasped)
 * @param graspFailures failed grasp attempts before the one that succeeds, drawn per run; null for a grasp that
 *                    succeeds within 1 to 4 attempts, as in the recordings (implies {@code grasp})
 * @param lateTurn    ticks the tree waits, after the first battery reading below the charger level, before it
 *                    turns to the charging station, drawn per run; null for a tree that turns at the early warning
 * @param tickPeriod  seconds between two ticks of the tree, drawn per run; null for the period drawn with the
 *                    other physical parameters (0.2 to 1 s)
 */
public record Novelties(int aborts, AbortOn abortOn, Span stuck, Span slowdown, Span drainFactor, String newLocation,
                        boolean noTicks, Span gap, Span neverArrives, boolean grasp, Span graspFailures,
                        Span lateTurn, Span tickPeriod) {

    /** The navigations that a blocked path can abort. */
    public enum AbortOn {
        /** The way to the tour location (the tree's {@code GoToDestination}). */
        DESTINATION,
        /** The way to the charging station ({@code GoToChargingStation}); a {@code direct} run never goes there. */
        STATION,
        /** Whichever navigation comes first. */
        ANY;

        /** The name used on the command line: {@code destination}, {@code station}, {@code any}. */
        public String id() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** The value named {@code id}, case-insensitively. */
        public static AbortOn fromId(String id) {
            for (AbortOn a : values()) {
                if (a.id().equalsIgnoreCase(id.trim())) {
                    return a;
                }
            }
            throw new IllegalArgumentException("unknown navigation '" + id + "' (expected destination, station or any)");
        }
    }

    /** How long a blocked robot stays stuck, by default: long enough to drain the battery visibly. */
    public static final Span DEFAULT_STUCK = new Span(10.0, 40.0);

    /** No novelty: the runs and logs of the thesis's scenarios. */
    public static final Novelties NONE = new Novelties(0, AbortOn.ANY, DEFAULT_STUCK, Span.ONE, Span.ONE, null,
            false, null, null, false, null, null, null);

    /** More aborts than this cannot fit in a run's hour; a typo is more likely. */
    static final int MAX_ABORTS = 10;

    /** A name a location port can carry ({@code /GoToGoToClient/<name>}). */
    private static final Pattern LOCATION_NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_]*");
    /** Names the simulator already uses: a "new" location must be none of them. */
    private static final Set<String> TAKEN = Set.of(Components.KITCHEN, Components.CHARGING_STATION, "start");

    public Novelties {
        if (aborts < 0 || aborts > MAX_ABORTS) {
            throw new IllegalArgumentException("aborts must be between 0 and " + MAX_ABORTS + ", got " + aborts);
        }
        if (abortOn == null || stuck == null || slowdown == null || drainFactor == null) {
            throw new IllegalArgumentException("abortOn, stuck, slowdown and drainFactor are required");
        }
        stuck.check("stuck time (seconds)", 1.0, 600.0);
        slowdown.check("slowdown factor", 0.1, 10.0);
        drainFactor.check("drain factor", 0.1, 10.0);
        if (gap != null) {
            gap.check("gap between runs (seconds)", 0.0, 3600.0);
        }
        if (neverArrives != null) {
            neverArrives.check("ticks stuck for good", 1.0, 3000.0);
        }
        if (graspFailures != null) {
            graspFailures.check("failed grasp attempts", 0.0, 500.0);
            grasp = true;
        }
        if (lateTurn != null) {
            lateTurn.check("ticks of the late turn", 0.0, 1000.0);
        }
        if (tickPeriod != null) {
            tickPeriod.check("tick period (seconds)", 0.05, 5.0);
        }
        if (newLocation != null && (!LOCATION_NAME.matcher(newLocation).matches() || TAKEN.contains(newLocation))) {
            throw new IllegalArgumentException("the new location must be a name of letters, digits and '_' other "
                    + "than " + String.join(", ", TAKEN.stream().sorted().toList()) + ", got '" + newLocation + "'");
        }
    }

    /** The novelties of before the grasp, the late turn and the lost navigation: none of these. */
    public Novelties(int aborts, AbortOn abortOn, Span stuck, Span slowdown, Span drainFactor, String newLocation,
                     boolean noTicks, Span gap) {
        this(aborts, abortOn, stuck, slowdown, drainFactor, newLocation, noTicks, gap, null, false, null, null, null);
    }

    /** Whether the simulated events differ from a default run's (not only their printing). */
    public boolean changesRuns() {
        return aborts > 0 || !slowdown.isOne() || !drainFactor.isOne() || newLocation != null || neverArrives != null
                || grasp || lateTurn != null || tickPeriod != null;
    }

    /** Whether any novelty is asked for: the truth then says what happened. */
    public boolean any() {
        return changesRuns() || noTicks || gap != null;
    }

    /** The name of the tour location the tree heads for. */
    public String destination() {
        return newLocation == null ? Components.KITCHEN : newLocation;
    }

    /**
     * The place whose way is lost for good with {@link #neverArrives}: the charging station with
     * {@code --abort-on station} (the short leg a {@code recharge} run takes at the Early Warning), else the tour
     * location (the long leg).
     */
    public String lostWay() {
        return abortOn == AbortOn.STATION ? Components.CHARGING_STATION : destination();
    }

    /** How many blocked-path aborts a run of {@code scenario} must show: none where no navigation may be blocked. */
    int abortsIn(Scenario scenario) {
        return scenario == Scenario.DIRECT && abortOn == AbortOn.STATION ? 0 : aborts;
    }

    public Novelties withAborts(int value, AbortOn on) {
        return new Novelties(value, on, stuck, slowdown, drainFactor, newLocation, noTicks, gap, neverArrives, grasp,
                graspFailures, lateTurn, tickPeriod);
    }

    public Novelties withStuck(Span value) {
        return new Novelties(aborts, abortOn, value, slowdown, drainFactor, newLocation, noTicks, gap, neverArrives,
                grasp, graspFailures, lateTurn, tickPeriod);
    }

    public Novelties withSlowdown(Span value) {
        return new Novelties(aborts, abortOn, stuck, value, drainFactor, newLocation, noTicks, gap, neverArrives, grasp,
                graspFailures, lateTurn, tickPeriod);
    }

    public Novelties withDrainFactor(Span value) {
        return new Novelties(aborts, abortOn, stuck, slowdown, value, newLocation, noTicks, gap, neverArrives, grasp,
                graspFailures, lateTurn, tickPeriod);
    }

    public Novelties withNewLocation(String value) {
        return new Novelties(aborts, abortOn, stuck, slowdown, drainFactor, value, noTicks, gap, neverArrives, grasp,
                graspFailures, lateTurn, tickPeriod);
    }

    public Novelties withNoTicks(boolean value) {
        return new Novelties(aborts, abortOn, stuck, slowdown, drainFactor, newLocation, value, gap, neverArrives,
                grasp, graspFailures, lateTurn, tickPeriod);
    }

    /** The robot gets stuck for good on its way to the tour location; the log ends {@code ticks} later. */
    public Novelties withNeverArrives(Span ticks) {
        return new Novelties(aborts, abortOn, stuck, slowdown, drainFactor, newLocation, noTicks, gap, ticks, grasp,
                graspFailures, lateTurn, tickPeriod);
    }

    /** A grasp at the tour location, {@code failures} failed attempts before it succeeds (null: 0 to 3). */
    public Novelties withGrasp(boolean value, Span failures) {
        return new Novelties(aborts, abortOn, stuck, slowdown, drainFactor, newLocation, noTicks, gap, neverArrives,
                value, failures, lateTurn, tickPeriod);
    }

    /** The tree turns to the charging station {@code ticks} after the first reading below the charger level. */
    public Novelties withLateTurn(Span ticks) {
        return new Novelties(aborts, abortOn, stuck, slowdown, drainFactor, newLocation, noTicks, gap, neverArrives,
                grasp, graspFailures, ticks, tickPeriod);
    }

    /** Ticks of the tree {@code seconds} apart instead of the period drawn with the physical parameters. */
    public Novelties withTickPeriod(Span seconds) {
        return new Novelties(aborts, abortOn, stuck, slowdown, drainFactor, newLocation, noTicks, gap, neverArrives,
                grasp, graspFailures, lateTurn, seconds);
    }

    /**
     * A closed range of values, one drawn per use from a seeded stream; {@code low == high} is a fixed value.
     *
     * @param low  the smallest value
     * @param high the largest value, at least {@code low}
     */
    public record Span(double low, double high) {

        /** The neutral factor. */
        public static final Span ONE = new Span(1.0, 1.0);

        public Span {
            if (!Double.isFinite(low) || !Double.isFinite(high) || high < low) {
                throw new IllegalArgumentException("a range needs finite low <= high, got " + low + ".." + high);
            }
        }

        /** {@code "12"} or {@code "5..30"}. */
        public static Span parse(String text) {
            String t = text.strip();
            int dots = t.indexOf("..");
            try {
                if (dots < 0) {
                    double v = Double.parseDouble(t);
                    return new Span(v, v);
                }
                return new Span(Double.parseDouble(t.substring(0, dots).strip()),
                        Double.parseDouble(t.substring(dots + 2).strip()));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("expected a number or a range LOW..HIGH, got '" + text + "'", e);
            }
        }

        boolean isOne() {
            return low == 1.0 && high == 1.0;
        }

        /** One value: {@code low} when fixed (nothing drawn), else uniform in [low, high). */
        double draw(SplittableRandom r) {
            return low == high ? low : r.nextDouble(low, high);
        }

        void check(String what, double min, double max) {
            if (low < min || high > max) {
                throw new IllegalArgumentException(what + " must be within " + min + ".." + max + ", got " + this);
            }
        }

        @Override
        public String toString() {
            return low == high ? Double.toString(low) : low + ".." + high;
        }
    }
}
