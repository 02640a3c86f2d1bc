package dev.predmon.compact;

import java.util.List;

/**
 * The outputs a query's answer passes through when it changes. For a continuous quantity read at intervals
 * (a battery level in bands) a jump from one band to a distant one crossed every band in between; emitting one
 * pair per band crossed makes the compacted trace the same whether a robot reads the level every 0.1 s or every
 * 5 s. For any other answer the path is just the new answer.
 */
@FunctionalInterface
public interface BandPath {

    /**
     * The answers from {@code from} to {@code to}, in the order they are emitted.
     *
     * @param from the query's previous answer, or null for its first
     * @param to   the new answer, different from {@code from}
     * @return the answers to emit in order, ending with {@code to}; never empty
     */
    List<String> path(String from, String to);
}
