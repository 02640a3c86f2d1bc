package dev.predmon.evaluate;

import dev.predmon.learn.ScenarioSpec;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Deterministic K-fold assignment, run by run: within each scenario the logs (sorted by name, as
 * {@link ScenarioSpec#logs()} are) go to folds 0, 1, ..., K-1, 0, 1, ... in turn, so every fold gets a share of
 * every scenario and the same directory always gives the same folds.
 */
public final class Folds {

    private Folds() {
    }

    /** The fold of every log, in scenario then log order. */
    public static Map<Path, Integer> assign(List<ScenarioSpec> specs, int k) {
        if (k < 2) {
            throw new IllegalArgumentException("cross-validation needs at least 2 folds, got " + k);
        }
        Map<Path, Integer> fold = new LinkedHashMap<>();
        for (ScenarioSpec s : specs) {
            List<Path> logs = s.logs().stream().sorted().toList();
            for (int i = 0; i < logs.size(); i++) {
                fold.put(logs.get(i), i % k);
            }
        }
        return fold;
    }
}
