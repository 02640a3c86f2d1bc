package dev.predmon.property;

import dev.predmon.parse.Decimals;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

/**
 * The one reader of a property's value: the numeric replies to {@code command} of {@code protocol} (from the port
 * {@code from} to the port {@code to}, each optional), e.g. the battery level from {@code /BatteryComponent}.
 *
 * @param protocol Thrift service of the watched reply (a record without one, from the older format, matches)
 * @param command  method of the watched reply
 * @param from     the reply's sending port (the server); empty matches any
 * @param to       the reply's receiving port (the client); empty matches any
 */
public record ValueReader(String protocol, String command, String from, String to) {

    /** The watched numeric value carried by {@code r}, or NaN when {@code r} is not a watched reply or no number. */
    public double valueOf(LogRecord r) {
        // An empty protocol is the older log format, which has no Protocol line: match by command, as rules do.
        boolean protocolMatches = r.protocol().isEmpty() || protocol.equals(r.protocol());
        if (r.kind() != RecordKind.REPLY || !protocolMatches || !command.equals(r.command())
                || (!from.isEmpty() && !from.equals(r.from())) || (!to.isEmpty() && !to.equals(r.to()))) {
            return Double.NaN;
        }
        // Every reply of a watched sensor: read without the JDK parser's allocations, in the rules' number grammar.
        return Decimals.parse(r.reply().trim());
    }

    /** {@code Protocol/command from /Server to /Client}, with the ports that are given. */
    public String describeWithPorts() {
        return describe() + (from.isEmpty() ? "" : " from " + from) + (to.isEmpty() ? "" : " to " + to);
    }

    /** {@code Protocol/command}, as users name a message. */
    public String describe() {
        return protocol + "/" + command;
    }
}
