package dev.predmon.monitor;

import dev.predmon.compact.IoPair;
import dev.predmon.matching.Matching;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.PropertyChecker;

/**
 * One property followed through the runs of a log, whatever its kind: one prototype per property, started over by
 * one {@link #reset} per run (BeepBeep's {@code Slice}, Reelay's update/output). The {@link PropertyChecker} is the
 * only judge and reader of the property's value: a follower is told after it took each record and turns what it says
 * (violated now, holds again, in scope, the reading) into the property's events. Beside the checker's verdicts a
 * follower keeps the property's forecast (if its kind has one and the models learned it), its warning and when that
 * warning ends ({@link MonitorEvent.Recovered}).
 *
 * <p>{@link FollowBase} writes the part every kind shares once: the violation, "holds again", the end of an alarm at
 * the scope's close and at the run's end, the matching's warning and the status. A new forecast kind extends it with
 * {@link FollowBase#follow} (its forecast at a record, and its warning) and, if the pairs move its forecast, {@link
 * #pair} and {@link #decide}; a kind forecast over the learned machines extends {@link TrackedFollow}, which writes
 * that forecast's pairs, start-overs, resets and status once.
 */
interface PropertyFollow {

    /** After the checker took {@code r}, the next record of the run: the property's events at that record. */
    void record(PropertyChecker checker, LogRecord r);

    /** A compacted pair, {@code step} its matching: the forecast after it (told before any warning of the pair). */
    default void pair(IoPair pair, Matching.Step step, LogRecord trigger) {
    }

    /** After the pair's forecasts and the matching's warning: the warning the property's own forecast decides. */
    default void decide(IoPair pair, Matching.Step step, LogRecord trigger) {
    }

    /** A gap in the trace at {@code line}: the run is novel from there. */
    default void gap(long line) {
    }

    /**
     * The property's obligation opened at {@code line} ended after {@code duration}, discharged or let go (as the
     * checker tells it).
     */
    default void closed(long line, double duration, boolean discharged) {
    }

    /** The run ends, {@code first} beginning the next: its violation there, if its deadline passed in between. */
    void overdue(PropertyChecker checker, LogRecord first);

    /** Whether the thesis's matching may warn of the property now. */
    boolean takesMatching();

    /** The matching warned of the property ({@code w}). */
    void matchingWarned(MonitorEvent.Warning w);

    /** The property's latest value in the run (a bound's), or null. */
    Double value();

    /** The run ended at {@code last}, its last record: an alarm still up ends ({@code run-ended}), {@code why}. */
    void runEnded(LogRecord last, String why);

    /** A new run: the property starts over. */
    void reset();

    /** The property now: its verdict, whether a warning of it is up and its latest forecast. */
    PropertyStatus status(PropertyChecker checker);

    /** Reports every forecast's times in seconds, a tick lasting {@code t}. */
    default void countTicksAs(TickSeconds t) {
    }
}
