package dev.predmon.learn;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * Deterministic K-fold assignment, run by run: within each scenario the logs (sorted by name, as
 * {@link ScenarioSpec#logs()} are) go to folds 0, 1, ..., K-1, 0, 1, ... in turn, so every fold gets a share of
 * every scenario and the same directory always gives the same folds. Asked for at least as many folds as there are
 * logs, each log is a fold of its own: leave-one-out.
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
        if (k >= specs.stream().mapToInt(s -> s.logs().size()).sum()) {
            for (ScenarioSpec s : specs) {
                s.logs().stream().sorted().forEach(log -> fold.put(log, fold.size()));
            }
            return fold;
        }
        for (ScenarioSpec s : specs) {
            List<Path> logs = s.logs().stream().sorted().toList();
            for (int i = 0; i < logs.size(); i++) {
                fold.put(logs.get(i), i % k);
            }
        }
        return fold;
    }

    /** How many folds {@code fold} uses (its folds are 0 to this minus one). */
    public static int used(Map<Path, Integer> fold) {
        return (int) fold.values().stream().distinct().count();
    }

    /** What a cross-validation asked for {@code asked} folds did instead, when it did: empty when it used them all. */
    public static Optional<String> instead(Map<Path, Integer> fold, int asked) {
        int used = used(fold);
        if (used == asked) {
            return Optional.empty();
        }
        int logs = fold.size();
        return Optional.of(used == logs && logs > 1 ? logs + " logs: leave-one-out (asked for " + asked
                + " folds)" : logs + " logs, at most " + used + " in a scenario: " + used + " folds (asked for "
                + asked + ")");
    }
}
