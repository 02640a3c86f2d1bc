package dev.predmon.simulate;

import java.io.UncheckedIOException;
import java.io.Writer;
import java.util.List;

/**
 * Writes a run's records at the pace of its simulated clock divided by {@code speed}, flushing after each
 * record, so that a live monitor tailing the file sees the log grow as it would on the robot.
 *
 * <p>Pacing follows the print order: a late reply is written when the record before it is due. The thread
 * sleeps against {@link System#nanoTime()}, so pauses do not accumulate drift. {@link #run()} returns early,
 * with the thread's interrupt flag set, when the thread is interrupted: the {@code demo} command can start
 * one on a thread and stop it.
 */
public final class RealtimeWriter implements Runnable {

    private final SimRun run;
    private final SimOptions options;
    private final Writer out;
    private final double speed;

    /**
     * @param speed simulated seconds per wall-clock second; must be positive
     */
    public RealtimeWriter(SimRun run, SimOptions options, Writer out, double speed) {
        if (!(speed > 0) || Double.isInfinite(speed)) {
            throw new IllegalArgumentException("speed must be a positive number, got " + speed);
        }
        this.run = run;
        this.options = options;
        this.out = out;
        this.speed = speed;
    }

    /**
     * Writes all records, sleeping before each until it is due.
     *
     * @throws UncheckedIOException if writing fails
     */
    @Override
    public void run() {
        List<SimEvent> order = LogWriter.printOrder(run, options);
        if (order.isEmpty()) {
            return;
        }
        long first = order.get(0).timeMicros();
        long due = first;
        long startNanos = System.nanoTime();
        for (SimEvent e : order) {
            due = Math.max(due, e.timeMicros());
            long target = startNanos + (long) ((due - first) * 1000.0 / speed);
            if (!sleepUntil(target)) {
                return;
            }
            LogWriter.writeOne(e, options, out);
        }
    }

    /** Sleeps until {@code System.nanoTime()} reaches {@code target}; false if interrupted. */
    private static boolean sleepUntil(long target) {
        long left;
        while ((left = target - System.nanoTime()) > 0) {
            try {
                Thread.sleep(left / 1_000_000, (int) (left % 1_000_000));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }
        return true;
    }
}
