package dev.predmon.simulate;

import com.fasterxml.jackson.annotation.JsonInclude;
import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.List;

/**
 * What the novelties of a run ({@link Novelties}) made happen, as the {@code novelties} object of its truth: when
 * the robot was stuck and its navigation aborted, how much slower it was, where its tour went, and where the run
 * lies in a log that holds several. Times are log times in seconds, like the rest of {@link Truth}.
 *
 * @param startTime   log time of the run's first record in the log
 * @param gapBefore   seconds of silence between the previous run's last record and this run's first, or null for
 *                    a log's first run
 * @param ticks       whether the log has the Tick records
 * @param destination the tour location the robot headed for
 * @param slowdown    the factor the robot's sampled speed was divided by (2: half as fast)
 * @param drainFactor the factor the battery's sampled drain was multiplied by (2: twice as fast)
 * @param aborts      the blocked-path aborts, in order
 * @param stuckForGood log time when the robot stopped for good on its way to the tour location, or null (the
 *                    JSON then leaves it out, as the three fields after it)
 * @param graspAttempts the {@code closeHand} attempts of the grasp at the tour location, or null without a grasp
 * @param lateTurnTicks ticks the tree waited, after the first reading below the charger level, before it turned to
 *                    the charging station, or null when it did not turn late
 */
public record NoveltyTruth(double startTime, Double gapBefore, boolean ticks, String destination, double slowdown,
                           double drainFactor, List<Abort> aborts,
                           @JsonInclude(JsonInclude.Include.NON_NULL) Double stuckForGood,
                           @JsonInclude(JsonInclude.Include.NON_NULL) Integer graspAttempts,
                           @JsonInclude(JsonInclude.Include.NON_NULL) Integer lateTurnTicks) {

    public NoveltyTruth {
        aborts = List.copyOf(aborts);
    }

    /** The facts of the novelties that existed before the lost navigation, the grasp and the late turn. */
    public NoveltyTruth(double startTime, Double gapBefore, boolean ticks, String destination, double slowdown,
                        double drainFactor, List<Abort> aborts) {
        this(startTime, gapBefore, ticks, destination, slowdown, drainFactor, aborts, null, null, null);
    }

    /**
     * One navigation that a blocked path aborted.
     *
     * @param location  where the robot was heading ({@code charging_station} or the tour location)
     * @param stuckFrom when the robot stopped at the blocked point
     * @param abortTime when the {@code getStatus} reply said ABORT (3)
     * @param retryTime when the tree sent {@code goTo} to the same location again, or null when it did not (the
 *                  battery had reached the early warning, so the tree headed for the charging station instead)
     * @param level     the last {@code level} reply before the abort, or null
     */
    public record Abort(String location, double stuckFrom, double abortTime, Double retryTime, Double level) {

        Abort shifted(double seconds) {
            return new Abort(location, stuckFrom + seconds, abortTime + seconds,
                    retryTime == null ? null : retryTime + seconds, level);
        }
    }

    /** The same facts for the run shifted {@code seconds} later in its log, {@code gapBefore} after the previous. */
    NoveltyTruth shifted(double seconds, Double gap) {
        return new NoveltyTruth(startTime + seconds, gap, ticks, destination, slowdown, drainFactor,
                aborts.stream().map(a -> a.shifted(seconds)).toList(),
                stuckForGood == null ? null : stuckForGood + seconds, graspAttempts, lateTurnTicks);
    }

    /**
     * Reads the aborts of {@code blockages} off the run's events: an abort counts once the tree has seen it, in a
     * {@code getStatus} reply of 3 for that location before any new {@code goTo} there.
     *
     * @param t0 log time of the run's simulated time 0 (its first tick)
     * @return the aborts the log shows; fewer than {@code blockages} when the tree halted a navigation before it
     *         asked for its status
     */
    static List<Abort> aborts(List<SimEvent> events, List<BlockedPaths.Blockage> blockages, double t0) {
        List<Abort> aborts = new ArrayList<>();
        for (BlockedPaths.Blockage b : blockages) {
            Abort a = observed(events, b, t0);
            if (a != null) {
                aborts.add(a);
            }
        }
        return aborts;
    }

    private static Abort observed(List<SimEvent> events, BlockedPaths.Blockage b, double t0) {
        double from = t0 + b.abortAt() - 1e-6;
        Double level = null;
        Double abortTime = null;
        for (SimEvent e : events) {
            boolean here = e.argument().equals(b.location());
            if (e.kind() == RecordKind.REPLY && e.command().equals("level") && abortTime == null) {
                level = Double.parseDouble(e.reply());
            }
            if (e.time() < from) {
                continue;
            }
            if (e.kind() == RecordKind.COMMAND && e.command().equals("goTo") && here) {
                return abortTime == null ? null
                        : new Abort(b.location(), micros(t0 + b.stuckFrom()), abortTime, e.time(), level);
            }
            if (abortTime == null && e.kind() == RecordKind.REPLY && e.command().equals("getStatus") && here
                    && e.reply().equals(Integer.toString(Components.ABORT))) {
                abortTime = e.time();
            }
        }
        return abortTime == null ? null : new Abort(b.location(), micros(t0 + b.stuckFrom()), abortTime, null, level);
    }

    /** Seconds rounded to the log's microseconds: the robot stopped at a tick, and the log has no finer clock. */
    private static double micros(double seconds) {
        return Math.round(seconds * 1e6) / 1e6;
    }
}
