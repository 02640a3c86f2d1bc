package dev.predmon.abstraction;

import dev.predmon.parse.Decimals;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.List;

/**
 * The built-in safety monitor's property: a numeric reply on one channel must not fall below a bound
 * (default: {@code level} replies from {@code /BatteryComponent} to {@code /BatteryReaderBatteryLevelClient}
 * below 20.0, the thesis's SCXML monitor of Section 3.3.1).
 *
 * @param name     shown to users, e.g. {@code battery level >= 20%}
 * @param protocol Thrift service of the watched reply (a record without one, from the older format, matches)
 * @param command  method of the watched reply
 * @param from     the reply's sending port (the server); empty matches any
 * @param to       the reply's receiving port (the client); empty matches any
 * @param below    the property is violated by the first value strictly below this
 * @param action   what an operator should do when the property is predicted to fail or fails, in words (e.g.
 *                 {@code send the robot to the charging station}), or null when the abstraction gives none
 * @param underWay the messages that say the action is under way (empty when the abstraction names none)
 */
public record SafetyRule(String name, String protocol, String command, String from, String to, double below,
                         String action, List<UnderWay> underWay) {

    public SafetyRule {
        underWay = underWay == null ? List.of() : List.copyOf(underWay);
    }

    /** A property without a recommended action. */
    public SafetyRule(String name, String protocol, String command, String from, String to, double below) {
        this(name, protocol, command, from, to, below, null, List.of());
    }

    /** A property with a recommended action, but no message that says it is under way. */
    public SafetyRule(String name, String protocol, String command, String from, String to, double below,
                      String action) {
        this(name, protocol, command, from, to, below, action, List.of());
    }

    /** The watched numeric value carried by {@code r}, or NaN when {@code r} is not a watched reply. */
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

    /** Whether {@code value} (from {@link #valueOf}) violates the property. */
    public boolean violatedBy(double value) {
        return value < below;
    }
}
