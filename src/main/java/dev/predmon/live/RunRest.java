package dev.predmon.live;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.Set;
import java.util.TreeSet;

/**
 * Whether a run's behaviour tree has come to rest: every action skill it started ({@code send_start} from the tree to
 * the skill) has been stopped since ({@code send_stop}). A log that goes quiet at rest is a run that ended (the robot
 * reached its goal and the tree stopped ticking); one that goes quiet with an action still running stopped mid-run (a
 * logger or robot that died, a robot that is stuck), which is what STALE is for. The abstraction drops this
 * tree-to-skill traffic from the traces, but every record of the log comes here.
 *
 * <p>A log with no such traffic (a capture without the tree's side) cannot tell, and its quiet stays STALE. Holds at
 * most one entry per skill.
 */
final class RunRest {

    private static final int MAX_SKILLS = 64;

    private final Set<String> running = new TreeSet<>();
    private boolean seen;

    /** Takes one record of the run. */
    void record(LogRecord r) {
        if (r.kind() != RecordKind.COMMAND) {
            return;
        }
        String command = r.command();
        if ("send_start".equals(command) && running.size() < MAX_SKILLS) {
            seen = true;
            running.add(skill(r.to()));
        } else if ("send_stop".equals(command)) {
            seen = true;
            running.remove(skill(r.to()));
        }
    }

    /** A new run: nothing runs, nothing seen. */
    void reset() {
        running.clear();
        seen = false;
    }

    /** Whether the tree started skills in this run, so that {@link #atRest()} means something. */
    boolean known() {
        return seen;
    }

    /** Whether no action the tree started is still running (only meaningful when {@link #known()}). */
    boolean atRest() {
        return seen && running.isEmpty();
    }

    /** The skills still running, by name ({@code GoToChargingStation}), sorted. */
    Set<String> running() {
        return Set.copyOf(running);
    }

    /** A skill's name from its server port: {@code /GoToDestination/BT_rpc/server} is {@code GoToDestination}. */
    static String skill(String port) {
        String p = port.startsWith("/") ? port.substring(1) : port;
        int slash = p.indexOf('/');
        return slash < 0 ? p : p.substring(0, slash);
    }
}
