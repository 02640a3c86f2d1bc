package dev.predmon.pipeline;

import dev.predmon.abstraction.RunRule;
import dev.predmon.parse.Clock;
import dev.predmon.parse.Decimals;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

/**
 * Tells, record by record, where a new run of the robot begins in a log that holds several ({@link RunRule}): where
 * the tree's tick counter starts again, or after a silence. It lives in the shared pipeline, so learn, evaluate and
 * watch cut a log into the same runs.
 */
final class RunSplitter {

    private final RunRule rule;
    private double lastTick = Double.NaN;
    private double lastTime = Double.NaN;

    RunSplitter(RunRule rule) {
        this.rule = rule;
    }

    /** Whether {@code r} is the first record of a new run (never the log's first record). */
    boolean startsRun(LogRecord r) {
        boolean starts = false;
        if (r.clock() == Clock.SECONDS && rule.silence() > 0 && !Double.isNaN(lastTime)
                && r.time() - lastTime > rule.silence()) {
            starts = true;
            lastTick = Double.NaN;
        }
        if (!Double.isNaN(r.time())) {
            lastTime = Double.isNaN(lastTime) ? r.time() : Math.max(lastTime, r.time());
        }
        if (r.kind() == RecordKind.TICK) {
            double n = tickNumber(r);
            if (!Double.isNaN(n)) {
                starts |= rule.tickRestart() && !Double.isNaN(lastTick) && n <= lastTick;
                lastTick = n;
            }
        }
        return starts;
    }

    void reset() {
        lastTick = Double.NaN;
        lastTime = Double.NaN;
    }

    /** A tick record's number: its Arguments, or NaN. */
    private static double tickNumber(LogRecord r) {
        return Decimals.parse(r.arguments().trim());
    }
}
