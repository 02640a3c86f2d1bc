package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.FleetListener;

import java.io.IOException;
import java.nio.file.Path;

/**
 * How every phase of {@link FleetBench} makes its fleets and follows them: the same models, matching as
 * {@code watch} does by default, followed as {@code watch} follows them, in scratch directories under one parent.
 *
 * @param pauseNanos the pause between two polls of a log that is polled
 * @param polling    poll every log ({@code watch --polling}) instead of waiting for notifications
 * @param dir        where the scratch directories go
 */
record FleetSetup(Abstraction abstraction, ModelSet models, long pauseNanos, boolean polling, Path dir) {

    /** A fleet telling {@code listener} its events (exact matching, the abstraction's confirm). */
    Fleet fleet(FleetListener listener) {
        return new Fleet(models, abstraction, 0, abstraction.confirm(), listener);
    }

    /** {@code fleet} followed over the logs of {@code logs} on a thread of its own, until closed. */
    Following follow(Fleet fleet, Path logs) {
        return new Following(fleet, logs, pauseNanos, polling);
    }

    /** A new scratch directory, deleted with its files when closed. */
    ScratchDir scratch(String prefix) throws IOException {
        return new ScratchDir(dir, prefix);
    }
}
