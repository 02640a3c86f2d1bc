package dev.predmon.evaluate;

import dev.predmon.forecast.Forecast;
import dev.predmon.monitor.MonitorEvent;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * What a replay saw on the way, beyond each run's verdict: per run, the forecast right after each compacted pair and
 * the warning as the monitor raised it, with its reason. Filled by {@link Replay#run}; read by {@code explain}.
 */
public final class Trail {

    /** A trail that keeps nothing: scoring a replay needs none, and keeps nothing per pair. */
    static final Trail NONE = new Trail(false);

    private final boolean keeps;
    private final Map<Integer, List<Forecast>> afterPairs = new HashMap<>();
    private final Map<Integer, MonitorEvent.Warning> warnings = new HashMap<>();

    /** An empty trail, for {@link Replay#run} to fill. */
    public Trail() {
        this(true);
    }

    private Trail(boolean keeps) {
        this.keeps = keeps;
    }

    /** Takes the monitor's forecast of {@code run} when it has seen {@code pairs} pairs of that run. */
    void forecast(int run, long pairs, Forecast f) {
        if (!keeps) {
            return;
        }
        List<Forecast> list = afterPairs.computeIfAbsent(run, r -> new ArrayList<>());
        if (pairs > list.size()) {
            list.add(f); // the first forecast once a pair came is the one after it; readings between pairs follow
        }
    }

    void warning(int run, MonitorEvent.Warning w) {
        if (keeps && w != null) {
            warnings.putIfAbsent(run, w); // the run's first warning: a later one follows a recovery
        }
    }

    /** The forecast after each pair of {@code run}, in pair order; empty without a forecast. */
    public List<Forecast> afterPairs(int run) {
        return List.copyOf(afterPairs.getOrDefault(run, List.of()));
    }

    /** The warning raised in {@code run}, if any. */
    public Optional<MonitorEvent.Warning> warning(int run) {
        return Optional.ofNullable(warnings.get(run));
    }
}
