package dev.predmon.property;

import dev.predmon.parse.Clock;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.List;

/**
 * A run written by hand, record by record, as the R1 system's monitor prints it: ticks of the tree, battery readings,
 * navigation and grasping. Lines are numbered 1, 2, 3, ... (one per record, so a test reads them off its own
 * list); times are the tick number, as in a console capture without time stamps, unless {@link #at} sets one.
 */
final class Trace {

    private final List<LogRecord> records = new ArrayList<>();
    private long tick;
    private Double time;

    /** The next tick of the tree. */
    Trace tick() {
        tick++;
        return add(RecordKind.TICK, "/tick/monitor", "/monitor", "Tick", "", Long.toString(tick), "");
    }

    /** {@code n} ticks of the tree. */
    Trace ticks(int n) {
        for (int i = 0; i < n; i++) {
            tick();
        }
        return this;
    }

    /** From here on, records carry time stamps in seconds, starting at {@code t}. */
    Trace at(double t) {
        time = t;
        return this;
    }

    Trace level(String reply) {
        return call("/BatteryReaderBatteryLevelClient", "/BatteryComponent", "BatteryReader", "level", "", reply);
    }

    Trace level(double value) {
        return level(Double.toString(value));
    }

    /** A goTo: the command carries the destination, the reply too. */
    Trace goTo(String location) {
        add(RecordKind.COMMAND, "/GoToGoToClient/" + location, "/GoToComponent", "GoTo", "goTo", location, "");
        return add(RecordKind.REPLY, "/GoToComponent", "/GoToGoToClient/" + location, "GoTo", "goTo", "", location);
    }

    Trace status(String location, int status) {
        return call("/GoToGoToClient/" + location, "/GoToComponent", "GoTo", "getStatus", location,
                Integer.toString(status));
    }

    Trace halt(String location) {
        return call("/GoToGoToClient/" + location, "/GoToComponent", "GoTo", "halt", location, "");
    }

    Trace closeHand() {
        return call("/ArmServiceFetchClient", "/ArmComponent", "ArmService", "closeHand", "", "27503");
    }

    Trace hasGrasped(boolean grasped) {
        return call("/ArmServiceFetchClient", "/ArmComponent", "ArmService", "hasGrasped", "", grasped ? "1" : "0");
    }

    /** A command and its reply. */
    Trace call(String client, String server, String protocol, String command, String arg, String reply) {
        add(RecordKind.COMMAND, client, server, protocol, command, arg, "");
        return add(RecordKind.REPLY, server, client, protocol, command, arg, reply);
    }

    private Trace add(RecordKind kind, String from, String to, String protocol, String command, String arg,
                      String reply) {
        long line = records.size() + 1L;
        Clock clock = time == null ? Clock.TICKS : Clock.SECONDS;
        double t = time == null ? tick : time;
        records.add(new LogRecord(line, t, "DEBUG", kind, from, to, protocol, command, arg, reply, clock));
        return this;
    }

    /** The line the next record will have. */
    long next() {
        return records.size() + 1L;
    }

    List<LogRecord> records() {
        return List.copyOf(records);
    }

    /** Checks {@code properties} on the run; the verdicts, and the violations told as they came. */
    static Checked check(List<Property> properties, Trace run) {
        List<String> told = new ArrayList<>();
        PropertyChecker c = new PropertyChecker(properties, (i, p, v) -> told.add(p.id() + "@" + v.line()));
        run.records().forEach(c::accept);
        return new Checked(c, told);
    }

    record Checked(PropertyChecker checker, List<String> told) {
        Verdict verdict(int i) {
            return checker.verdict(i);
        }
    }
}
