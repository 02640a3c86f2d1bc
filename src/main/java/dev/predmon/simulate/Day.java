package dev.predmon.simulate;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * A robot's day: several runs one after another in one log, as the monitor keeps printing across missions. Each run
 * is simulated on its own (its tick counter starts again, as the real tree's does) and shifted in time to begin a
 * pause after the previous one ended.
 *
 * <p>The pause is 5 s unless {@link Novelties#gap()} draws one per gap, from a stream seeded by the first seed. It
 * is the silence a reader of the log sees: from the last printed record of one run to the first of the next, which
 * without Tick records is a message, not a tick.
 */
public final class Day {

    /** The pause between two runs: the robot is handed its next mission. */
    static final long PAUSE_MICROS = 5_000_000L;

    private Day() {
    }

    /**
     * The runs of {@code scenarios} in turn ({@code runs} of them, the list cycled), seeds {@code seed},
     * {@code seed + 1}, ...; each run's events shifted to start after the previous run's last one.
     */
    public static List<SimRun> simulate(List<Scenario> scenarios, long seed, int runs, SimOptions options) {
        Novelties novelties = options.novelties();
        SplittableRandom gaps = novelties.gap() == null ? null : new SplittableRandom(seed ^ 0x6761707321L);
        List<SimRun> day = new ArrayList<>();
        long end = Long.MIN_VALUE;
        long lines = 0;
        for (int k = 0; k < runs; k++) {
            SimRun run = Simulator.run(scenarios.get(k % scenarios.size()), seed + k, options);
            long first = Simulator.firstPrinted(run.events(), novelties.noTicks()).timeMicros();
            long pause = gaps == null ? PAUSE_MICROS : Math.round(novelties.gap().draw(gaps) * 1e6);
            long shift = end == Long.MIN_VALUE ? 0 : Math.max(0, end + pause - first);
            Double gap = end == Long.MIN_VALUE ? null : (first + shift - end) / 1e6;
            SimRun shifted = shift(run, shift, gap, lines);
            day.add(shifted);
            end = shifted.events().get(shifted.events().size() - 1).timeMicros();
            lines += (long) LogWriter.printOrder(run, options).size() * LogWriter.linesPerRecord(options);
        }
        return List.copyOf(day);
    }

    /** The run with every event {@code micros} later. */
    static SimRun shift(SimRun run, long micros) {
        return shift(run, micros, run.truth().novelties() == null ? null : run.truth().novelties().gapBefore(), 0);
    }

    /**
     * The run with every event {@code micros} later, {@code gap} seconds after the previous run of its log, its
     * records {@code lines} lines further down.
     */
    private static SimRun shift(SimRun run, long micros, Double gap, long lines) {
        if (micros == 0 && lines == 0 && (run.truth().novelties() == null || gap == null)) {
            return run;
        }
        List<SimEvent> events = new ArrayList<>(run.events().size());
        for (SimEvent e : run.events()) {
            events.add(new SimEvent(e.timeMicros() + micros, e.kind(), e.from(), e.to(), e.protocol(), e.command(),
                    e.argument(), e.reply()));
        }
        return new SimRun(run.scenario(), run.seed(), run.options(), events, run.truth().shifted(micros / 1e6, gap, lines));
    }
}
