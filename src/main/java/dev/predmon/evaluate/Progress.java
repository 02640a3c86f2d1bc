package dev.predmon.evaluate;

/** Told after each step of a long evaluation (learning a fold, judging a log). */
@FunctionalInterface
public interface Progress {

    /** Nothing to report. */
    Progress NONE = (done, total, what) -> {
    };

    /** {@code done} of {@code total} steps are finished; {@code what} names the last one. */
    void step(int done, int total, String what);
}
