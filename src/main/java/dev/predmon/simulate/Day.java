package dev.predmon.simulate;

import java.util.ArrayList;
import java.util.List;

/**
 * A robot's day: several runs one after another in one log, as the monitor keeps printing across missions. Each run
 * is simulated on its own (its tick counter starts again, as the real tree's does) and shifted in time to begin a
 * pause after the previous one ended.
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
        List<SimRun> day = new ArrayList<>();
        long end = Long.MIN_VALUE;
        for (int k = 0; k < runs; k++) {
            SimRun run = Simulator.run(scenarios.get(k % scenarios.size()), seed + k, options);
            long first = run.events().get(0).timeMicros();
            long shift = end == Long.MIN_VALUE ? 0 : Math.max(0, end + PAUSE_MICROS - first);
            SimRun shifted = shift(run, shift);
            day.add(shifted);
            end = shifted.events().get(shifted.events().size() - 1).timeMicros();
        }
        return List.copyOf(day);
    }

    /** The run with every event {@code micros} later. */
    static SimRun shift(SimRun run, long micros) {
        if (micros == 0) {
            return run;
        }
        List<SimEvent> events = new ArrayList<>(run.events().size());
        for (SimEvent e : run.events()) {
            events.add(new SimEvent(e.timeMicros() + micros, e.kind(), e.from(), e.to(), e.protocol(), e.command(),
                    e.argument(), e.reply()));
        }
        return new SimRun(run.scenario(), run.seed(), run.options(), events, run.truth().shifted(micros / 1e6));
    }
}
