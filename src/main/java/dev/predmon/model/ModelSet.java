package dev.predmon.model;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastModel;
import net.automatalib.automaton.transducer.CompactMealy;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A model directory as loaded: its index, every machine and the forecast's statistics.
 *
 * @param dir      where it was read from
 * @param index    the index
 * @param models   every machine, scenario by scenario in index order
 * @param forecast the forecast's statistics, or null when the directory was learned without them
 */
public record ModelSet(Path dir, ModelIndex index, List<LearnedModel> models, ForecastModel forecast) {

    /** Models without a forecast. */
    public ModelSet(Path dir, ModelIndex index, List<LearnedModel> models) {
        this(dir, index, models, null);
    }

    /** The machines by id, in model order: what the forecast follows. */
    public Map<String, CompactMealy<String, String>> machines() {
        Map<String, CompactMealy<String, String>> machines = new LinkedHashMap<>();
        models.forEach(m -> machines.put(m.id(), m.machine()));
        return machines;
    }

    /** Whether some scenario is faulty: without one, no warning can ever be raised. */
    public boolean hasFaulty() {
        return index.scenarios().stream().anyMatch(ModelIndex.Scenario::faulty);
    }

    /** Whether some scenario is nominal. */
    public boolean hasNominal() {
        return index.scenarios().stream().anyMatch(s -> !s.faulty());
    }

    /**
     * {@code abstraction} as these models were learned with it: with the hysteresis {@code learn} estimated from the
     * training runs' sensor noise ({@link ModelIndex.AbstractionInfo#hysteresis()}), so that a log abstracts as the
     * training logs did.
     */
    public Abstraction tune(Abstraction abstraction) {
        return abstraction.withLearnedHysteresis(index.abstraction().hysteresis());
    }
}
