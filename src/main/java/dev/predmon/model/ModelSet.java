package dev.predmon.model;

import java.nio.file.Path;
import java.util.List;

/**
 * A model directory as loaded: its index and every machine.
 *
 * @param dir    where it was read from
 * @param index  the index
 * @param models every machine, scenario by scenario in index order
 */
public record ModelSet(Path dir, ModelIndex index, List<LearnedModel> models) {

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
    public dev.predmon.abstraction.Abstraction tune(dev.predmon.abstraction.Abstraction abstraction) {
        return abstraction.withLearnedHysteresis(index.abstraction().hysteresis());
    }
}
