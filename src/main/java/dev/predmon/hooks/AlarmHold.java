package dev.predmon.hooks;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * The hold time of the robot's alarms: a recovery's command runs only once the alarm has stayed over for the hold
 * time (wall clock), so that a reading flapping at the bound (19.9, 20.1, 19.9, ...) does not run a warning, a
 * violation and a recovery command at every crossing.
 *
 * <p>For each log and property: a warning or violation runs its command at once, and the robot's alarm is up. A
 * recovery waits for the hold time. When the same property's alarm is raised again in the same run before then, the
 * recovery never runs and the robot's alarm stays up: a warning or violation less than the hold time after a
 * recovery runs no command unless it says more than the robot heard (a violation after a warning), and is reported
 * once. The monitor's events are not held: stdout, the page and {@code /metrics} get every one. A new run of the log,
 * and the end of watch, run a held recovery at once.
 */
final class AlarmHold implements AutoCloseable {

    /** What an event says of a property's alarm, in order of severity. */
    enum Kind { NONE, WARNING, VIOLATION, RECOVERY }

    private record Key(String log, String property) {
    }

    /** One property's alarm as the robot heard it. */
    private static final class State {
        int run;
        Kind heard = Kind.NONE;
        Runnable recovery;
        ScheduledFuture<?> due;
        /** When the latest recovery came (System.nanoTime), 0 before any. */
        long recoveredAt;
        boolean said;
    }

    private final long holdNanos;
    private final Consumer<String> report;
    private final Map<Key, State> alarms = new HashMap<>();
    private ScheduledThreadPoolExecutor timer;

    /** @param hold zero for none: every event runs its command at once */
    AlarmHold(Duration hold, Consumer<String> report) {
        if (hold.isNegative()) {
            throw new IllegalArgumentException("the hold time must not be negative, got " + hold);
        }
        this.holdNanos = hold.toNanos();
        this.report = report;
    }

    /**
     * An event of {@code property} (null for none) of {@code log}'s run {@code run}: {@code submit} queues its
     * command, now, later or never; {@code what} names the event in a report line ({@code --on-warning: warning of
     * robot-1.log line 120}).
     */
    synchronized void event(String log, String property, int run, Kind kind, Runnable submit, String what) {
        if (holdNanos == 0) {
            submit.run();
            return;
        }
        Key key = new Key(log, property == null ? "" : property);
        State s = alarms.computeIfAbsent(key, k -> new State());
        if (s.run != run) {
            release(s); // the alarm of the run before ends with its run
            s.heard = Kind.NONE;
            s.recoveredAt = 0;
            s.run = run;
        }
        long now = System.nanoTime();
        if (kind == Kind.RECOVERY) {
            release(s);
            s.recovery = submit;
            s.recoveredAt = now;
            s.due = timer().schedule(() -> due(key, s), holdNanos, TimeUnit.NANOSECONDS);
            return;
        }
        if (s.recovery != null) {
            // raised again within the hold: the recovery is never sent
            s.due.cancel(false);
            s.recovery = null;
            s.due = null;
        }
        if (s.recoveredAt != 0 && now - s.recoveredAt < holdNanos && s.heard.compareTo(kind) >= 0) {
            // the robot's alarm is still up, at this level or above: it hears nothing new
            if (!s.said) {
                s.said = true;
                report.accept(what + ": not run, the alarm it raises again recovered less than "
                        + seconds(holdNanos) + " s before, so the robot's alarm is still up; its recovery waits "
                        + "until the alarm stays over for " + seconds(holdNanos) + " s");
            }
            return;
        }
        s.heard = kind.compareTo(s.heard) > 0 ? kind : s.heard;
        submit.run();
    }

    /** The hold of {@code s} has passed with no new alarm: its recovery runs, and the robot's alarm is over. */
    private synchronized void due(Key key, State s) {
        if (alarms.get(key) == s && s.recovery != null) {
            release(s);
            alarms.remove(key);
        }
    }

    /** Runs the recovery {@code s} holds, if any, now. */
    private void release(State s) {
        if (s.recovery == null) {
            return;
        }
        if (s.due != null) {
            s.due.cancel(false);
        }
        Runnable r = s.recovery;
        s.recovery = null;
        s.due = null;
        s.heard = Kind.NONE;
        s.said = false;
        r.run();
    }

    private ScheduledThreadPoolExecutor timer() {
        if (timer == null) {
            timer = new ScheduledThreadPoolExecutor(1, r -> {
                Thread t = new Thread(r, "predmon-hook-hold");
                t.setDaemon(true);
                return t;
            });
            timer.setRemoveOnCancelPolicy(true);
        }
        return timer;
    }

    /** Forgets {@code log}'s alarms (its log was deleted long ago), running a recovery still held first. */
    synchronized void forget(String log) {
        for (var i = alarms.entrySet().iterator(); i.hasNext(); ) {
            var e = i.next();
            if (e.getKey().log().equals(log)) {
                release(e.getValue());
                i.remove();
            }
        }
    }

    /** Runs every held recovery now (watch ends: the robot hears that its alarms are over). */
    @Override
    public synchronized void close() {
        List<State> held = new ArrayList<>(alarms.values());
        alarms.clear();
        held.forEach(this::release);
        if (timer != null) {
            timer.shutdownNow();
        }
    }

    static String seconds(long nanos) {
        double s = nanos / 1e9;
        return s == Math.rint(s) ? Long.toString((long) s) : Double.toString(s);
    }
}
