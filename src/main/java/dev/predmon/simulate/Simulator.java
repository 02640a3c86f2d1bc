package dev.predmon.simulate;

import dev.predmon.parse.RecordKind;
import dev.predmon.simulate.BehaviorTree.Node;
import dev.predmon.simulate.BehaviorTree.Status;
import dev.predmon.simulate.SimParameters.Point;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;

/**
 * Simulates the case study (thesis Chapter 3): the behaviour tree ticks its skills, the skills call the
 * battery and navigation components, and every call is recorded as the YARP monitor would intercept it.
 *
 * <p>A run is a pure function of scenario, seed and options. The physical parameters are drawn from the
 * seed within wide ranges, because a real robot varies a lot; the geometry is then placed so that the
 * scenario's story is likely (e.g. the charging station {@code (earlyWarning - arrivalLevel) / drainPerMetre}
 * metres from where the robot should turn), the run is simulated, and if its messages do not tell the story
 * (checked on the events, as a reader of the log would) the next sample of the same random stream is tried.
 *
 * <p>Ranges: tick period 0.2-1.0 s; speed 0.3-1.0 m/s; drain 0.4-2.5 %/s moving, 0-0.03 %/s idle, with
 * +-0-30% noise per tick; charge 0.8-5 %/s; battery sensor period tick-4 s; start level 70-100 (at least
 * early warning + 5); tolerance 0.05-0.25 m. {@code direct}: arrival level early warning + 2 .. start - 3.
 * {@code recharge}: planned station arrival level max(21, early warning - 20) + 2 .. early warning - 2 (the
 * thesis's margin, see {@link RunFacts#rechargeMinLevel}), kitchen up to half a full
 * battery's range past the turn. {@code depleted}: station (early warning + 5..60)% of range past the turn.
 *
 * <p>Novelties ({@link SimOptions#novelties()}) draw from a stream of their own, so that a run without them is
 * the same as before they existed. A slowdown or drain factor is applied after the geometry was placed (the world
 * stays, the robot changes), and a sample whose novelty breaks the story, or whose aborts the tree never saw, is
 * rejected like any other: every run keeps its scenario's outcome, and the truth says what the novelties did.
 *
 * <p>The tree and the components note what they do in a {@link Ledger}; {@link PropertyJudge} judges the truth's
 * properties from it, at the lines of the log as the run's options print it.
 */
public final class Simulator {

    /** Samples tried before giving up on a scenario (typically fewer than 5 are needed). */
    static final int MAX_ATTEMPTS = 2000;
    /** Simulated seconds after which a run is abandoned as not telling its story. */
    static final double TIME_CAP = 3600.0;

    private static final long EPOCH_BASE = 1_600_000_000L;
    private static final long EPOCH_SPREAD = 100_000_000L;

    private Simulator() {
    }

    /**
     * Simulates one run of {@code scenario}.
     *
     * @throws IllegalStateException if no sample tells the story (only with extreme early warnings)
     */
    public static SimRun run(Scenario scenario, long seed, SimOptions options) {
        // The time base has its own stream so that --epoch shifts the same run instead of sampling another.
        SplittableRandom clock = new SplittableRandom(seed ^ 0x9E3779B97F4A7C15L);
        long startMicros = clock.nextLong(200_000, 3_000_000);
        if (options.epoch()) {
            startMicros += (EPOCH_BASE + clock.nextLong(EPOCH_SPREAD)) * 1_000_000L;
        }
        SplittableRandom master = new SplittableRandom(seed);
        Novelties novelties = options.novelties();
        for (int attempt = 0; attempt < MAX_ATTEMPTS; attempt++) {
            SimParameters p = sample(scenario, options.earlyWarning(), master, attempt, startMicros);
            SplittableRandom noise = master.split();
            if (p == null) {
                continue;
            }
            SplittableRandom novel = novelties.changesRuns()
                    ? new SplittableRandom((seed * 0x2545F4914F6CDD1DL + attempt) ^ 0x6E6F76656C747921L) : null;
            double slowdown = novel == null ? 1.0 : novelties.slowdown().draw(novel);
            double drainFactor = novel == null ? 1.0 : novelties.drainFactor().draw(novel);
            if (slowdown != 1.0 || drainFactor != 1.0) {
                p = p.slowed(slowdown, drainFactor);
            }
            BlockedPaths blocked = novelties.aborts() > 0 ? new BlockedPaths(novelties, novel.split()) : null;
            if (novelties.tickPeriod() != null) {
                p = p.withTickPeriod(novelties.tickPeriod().draw(novel));
            }
            Mishaps m = Mishaps.draw(novelties, options.limits(), novel, blocked);
            if (m.lateTurn() != null && scenario == Scenario.RECHARGE) {
                p = m.lateTurn().relaidForRecharge(p, options.limits().navigationTicks(), novel);
                if (p == null) {
                    continue;
                }
            }
            Recorder recorded = simulate(scenario, p, options, startMicros, noise,
                    new SplittableRandom(seed * 0x5DEECE66DL + attempt), m);
            if (recorded == null) {
                continue;
            }
            List<SimEvent> events = recorded.events();
            RunFacts f = RunFacts.of(events, options.earlyWarning(), novelties.destination());
            if (!f.tell(scenario, options.earlyWarning(), m.arrives(scenario), m.rechargeFloor(options.earlyWarning()),
                    m.reachesStation())
                    || !m.kept(scenario)) {
                continue;
            }
            NoveltyTruth happened = null;
            double t0 = startMicros / 1e6;
            if (novelties.any()) {
                List<NoveltyTruth.Abort> aborts = blocked == null ? List.of()
                        : NoveltyTruth.aborts(events, blocked.happened(), t0);
                if (blocked != null && (aborts.size() != blocked.happened().size()
                        || aborts.size() != novelties.abortsIn(scenario))) {
                    continue;
                }
                happened = new NoveltyTruth(firstPrinted(events, novelties.noTicks()).time(), null,
                        !novelties.noTicks(), novelties.destination(), slowdown, drainFactor, aborts,
                        m.stuckForGood(t0), m.graspAttempts(), m.lateTurnTicks());
            }
            Truth truth = new Truth(scenario, scenario.faulty(), seed, p, f.violationTime(), f.violationLevel(),
                    f.turnTime(), f.turnLevel(), f.stationLevel(), f.endTime(), f.timeline(), happened,
                    properties(recorded, seed, options));
            return new SimRun(scenario, seed, options, events, truth);
        }
        throw new IllegalStateException("no sample of " + MAX_ATTEMPTS + " tells the " + scenario.id()
                + " story with early warning " + options.earlyWarning() + " (seed " + seed + ")");
    }

    /** Each property's verdict on the recorded run, at the lines of the log as {@code options} print it. */
    private static Map<String, PropertyTruth> properties(Recorder recorded, long seed, SimOptions options) {
        Map<String, PropertyJudge.Violation> first = PropertyJudge.judge(recorded.ledger(), options.limits());
        long[] lines = LogWriter.headerLines(recorded.events(), seed, options);
        Map<String, PropertyTruth> verdicts = new LinkedHashMap<>();
        for (String id : PropertyJudge.IDS) {
            PropertyJudge.Violation v = first.get(id);
            verdicts.put(id, v == null ? PropertyTruth.HOLDS
                    : new PropertyTruth(true, lines[v.event()], v.tick(), recorded.events().get(v.event()).time()));
        }
        return verdicts;
    }

    /** The first event a log prints: the first tick, or the first message when ticks are left out. */
    static SimEvent firstPrinted(List<SimEvent> events, boolean noTicks) {
        return events.stream().filter(e -> !noTicks || e.kind() != RecordKind.TICK).findFirst().orElseThrow();
    }

    /** Draws one set of parameters, or null when the draw cannot place the scenario's geometry. */
    private static SimParameters sample(Scenario scenario, double ew, SplittableRandom r, int attempt,
                                        long startMicros) {
        double tick = r.nextDouble(0.2, 1.0);
        double speed = r.nextDouble(0.3, 1.0);
        double drain = r.nextDouble(0.4, 2.5);
        double idle = r.nextDouble(0.0, 0.03);
        double noise = r.nextDouble(0.0, 0.3);
        double charge = r.nextDouble(0.8, 5.0);
        double sensor = r.nextDouble(tick, Math.max(tick, 4.0) + 1e-9);
        double startLow = Math.max(70.0, Math.min(ew + 5.0, 99.0));
        double start = r.nextDouble(startLow, 100.0 + 1e-9);
        double tolerance = r.nextDouble(0.05, 0.25);
        boolean echoes = r.nextBoolean();
        int tail = r.nextInt(1, 4);
        double heading = r.nextDouble(0, 2 * Math.PI);
        double perMetre = drain / speed;
        double range = 100.0 / perMetre;
        double toTurn = (start - ew) / perMetre;
        Point kitchen;
        Point station;
        switch (scenario) {
            case DIRECT -> {
                if (ew + 2.0 >= start - 3.0) {
                    return null;
                }
                double arrival = r.nextDouble(ew + 2.0, start - 3.0);
                kitchen = polar(Point.ORIGIN, (start - arrival) / perMetre, heading);
                station = polar(Point.ORIGIN, r.nextDouble(3.0, 25.0), heading + r.nextDouble(1.0, 5.3));
            }
            case RECHARGE -> {
                double lowest = RunFacts.rechargeMinLevel(ew) + 2.0;
                if (lowest >= ew - 2.0) {
                    return null;
                }
                Point turn = polar(Point.ORIGIN, toTurn, heading);
                kitchen = polar(Point.ORIGIN, toTurn + r.nextDouble(0.03, 0.5) * range, heading);
                double arrival = r.nextDouble(lowest, ew - 2.0);
                station = polar(turn, (ew - arrival) / perMetre, heading + r.nextDouble(-Math.PI, Math.PI));
            }
            case DEPLETED -> {
                Point turn = polar(Point.ORIGIN, toTurn, heading);
                kitchen = polar(Point.ORIGIN, toTurn + r.nextDouble(0.03, 0.5) * range, heading);
                station = polar(turn, (ew + r.nextDouble(5.0, 60.0)) / perMetre,
                        heading + r.nextDouble(-Math.PI, Math.PI));
            }
            default -> throw new IllegalArgumentException(scenario.toString());
        }
        return new SimParameters(attempt, tick, speed, drain, idle, noise, charge, sensor, start, tolerance,
                kitchen, station, echoes, startMicros / 1e6, tail);
    }

    /** Cheap early rejection; {@link RunFacts#tell} remains the judge of a finished run. */
    private static boolean storyBroken(Scenario scenario, Components c, double rechargeFloor) {
        return switch (scenario) {
            case DIRECT -> c.goToStationCount() > 0;
            case RECHARGE -> c.goToStationCount() > 1 || c.level() < rechargeFloor;
            case DEPLETED -> c.isAtLocation(Components.CHARGING_STATION);
        };
    }

    /** The point {@code distance} metres from {@code from} in the direction {@code angle} (radians). */
    static Point polar(Point from, double distance, double angle) {
        return new Point(from.x() + distance * Math.cos(angle), from.y() + distance * Math.sin(angle));
    }

    /**
     * Ticks the tree until it succeeds, the robot stops on an empty battery or the capture of a robot stuck for good
     * stops; null past the time cap or as soon as the run can no longer tell the story (which keeps rejected samples
     * cheap).
     */
    private static Recorder simulate(Scenario scenario, SimParameters p, SimOptions options, long startMicros,
                                     SplittableRandom noise, SplittableRandom sensor, Mishaps m) {
        double ew = options.earlyWarning();
        String destination = options.novelties().destination();
        Ledger ledger = new Ledger();
        // The components split the noise stream first and the recorder second, as they always did.
        Components c = new Components(p, noise.split(), options.noise(), sensor, destination, m.blocked(), m.lost(),
                ledger);
        Recorder r = new Recorder(noise.split(), ledger);
        Node root = BehaviorTree.build(c, r, ew, p.goToEchoesDestination(), destination, m.lateTurn(), m.arm());
        double floor = m.rechargeFloor(ew);
        int remaining = -1;
        for (int k = 0; k * p.tickPeriod() <= TIME_CAP; k++) {
            if (k > 0) {
                c.advance(p.tickPeriod());
            }
            r.tick(startMicros + Math.round(k * p.tickPeriod() * 1e6), k);
            Status s = root.tick();
            if (storyBroken(scenario, c, floor)) {
                return null;
            }
            if (m.lost() != null && m.lost().captureOver()) {
                return r;
            }
            if (remaining > 0) {
                if (--remaining == 0) {
                    return r;
                }
            } else if (s == Status.SUCCESS || c.stoppedEmpty()) {
                remaining = p.tailTicks();
            }
        }
        return null;
    }
}
