package dev.predmon.monitor;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Objects;

/**
 * A fleet's logs taken a slice at a time, so that a look at every log is spread over a period instead of done in one
 * go: each call gives the next of {@code count} slices of the logs as they were at the first slice of the round,
 * less those forgotten since.
 */
final class Slices<T> {

    private final int count;
    private List<T> round = new ArrayList<>();
    private int next;

    Slices(int count) {
        this.count = count;
    }

    /** The next slice of {@code logs}: after {@code count} calls, every log that was there at the first of them. */
    List<T> next(Collection<T> logs) {
        if (next == 0) {
            round = new ArrayList<>(logs);
        }
        int n = round.size();
        List<T> out = round.subList((int) ((long) next * n / count), (int) ((long) (next + 1) * n / count)).stream()
                .filter(Objects::nonNull).toList();
        next = (next + 1) % count;
        return out;
    }

    /** {@code log} is no longer followed: it is not given again, nor held. */
    void forget(T log) {
        int at = round.indexOf(log);
        if (at >= 0) {
            round.set(at, null); // the others keep their slices
        }
    }
}
