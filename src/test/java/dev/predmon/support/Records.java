package dev.predmon.support;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Builds record sequences of the case study by hand, as the monitor prints them (Tables 4.1/4.2 ports), for
 * tests that need exact control over what a run says and when.
 */
public final class Records {

    private final List<LogRecord> records = new ArrayList<>();
    private double time;
    private long line = 1;

    /** Advances the clock. */
    public Records at(double t) {
        time = t;
        return this;
    }

    /** A {@code level} query answered {@code value}. */
    public Records level(double value) {
        return call("/BatteryReaderBatteryLevelClient", "/BatteryComponent", "BatteryReader", "level", "",
                String.format(Locale.ROOT, "%.6f", value));
    }

    public Records charging(boolean charging) {
        return call("/BatteryReaderBatteryNotChargingClient", "/BatteryComponent", "BatteryReader", "charging_status",
                "", charging ? "1" : "0");
    }

    public Records isAt(String location, boolean at) {
        return call("/GoToIsAtClient/" + location, "/GoToComponent", "GoTo", "isAtLocation", location, at ? "1" : "0");
    }

    public Records goTo(String location) {
        return call("/GoToGoToClient/" + location, "/GoToComponent", "GoTo", "goTo", location, "");
    }

    public Records status(String location, int status) {
        return call("/GoToGoToClient/" + location, "/GoToComponent", "GoTo", "getStatus", location,
                Integer.toString(status));
    }

    public Records halt(String location) {
        return call("/GoToGoToClient/" + location, "/GoToComponent", "GoTo", "halt", location, "");
    }

    /** A command and, right after it, its reply. */
    public Records call(String client, String server, String protocol, String command, String arg, String reply) {
        add(RecordKind.COMMAND, client, server, protocol, command, arg, "");
        add(RecordKind.REPLY, server, client, protocol, command, arg, reply);
        return this;
    }

    private void add(RecordKind kind, String from, String to, String protocol, String command, String arg, String reply) {
        time += 0.001;
        records.add(new LogRecord(line, time, "DEBUG", kind, from, to, protocol, command, arg, reply));
        line += 7;
    }

    public List<LogRecord> list() {
        return List.copyOf(records);
    }

    /** The records as monitor log text (current format, tab-separated header). */
    public String text() {
        StringBuilder sb = new StringBuilder();
        for (LogRecord r : records) {
            String kind = r.kind() == RecordKind.COMMAND ? "Command" : "Reply";
            sb.append(String.format(Locale.ROOT, "%.6f\tDEBUG\t%s intercepted:%n", r.time(), kind))
                    .append("  From      : ").append(r.from()).append('\n')
                    .append("  To        : ").append(r.to()).append('\n')
                    .append("  Protocol  : ").append(r.protocol()).append('\n')
                    .append("  Command   : ").append(r.command()).append('\n')
                    .append("  Arguments : ").append(r.arguments()).append('\n')
                    .append("  Reply     : ").append(r.reply()).append('\n');
        }
        return sb.toString();
    }
}
