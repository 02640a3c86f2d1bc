package dev.predmon.property;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

/**
 * A message that says the safety property's recommended action is under way: the robot already does what an operator
 * would tell it to. Either the behaviour tree starts a skill ({@code skill}: a {@code send_start} to the skill's port,
 * {@code /GoToChargingStation/BT_rpc/server}), or a component is called ({@code command}, optionally of
 * {@code protocol} and with its first argument {@code argument}: a {@code goTo} with {@code charging_station}).
 *
 * <p>The action stops being under way when the tree stops that skill ({@code send_stop}), or when the same command
 * is called with another argument (the robot was sent elsewhere).
 *
 * @param skill    the skill's name, or null for a command
 * @param protocol the command's Thrift service, or null for any
 * @param command  the command, or null for a skill
 * @param argument the command's first argument, or null for any
 */
public record UnderWay(String skill, String protocol, String command, String argument) {

    /** Whether {@code r} says the action is under way from now. */
    public boolean starts(LogRecord r) {
        if (r.kind() != RecordKind.COMMAND) {
            return false;
        }
        if (skill != null) {
            return "send_start".equals(r.command()) && skill.equals(skillOf(r.to()));
        }
        return sameCommand(r) && (argument == null || argument.equals(firstArgument(r.arguments())));
    }

    /** Whether {@code r} says the action stopped: its skill stopped, or its command went elsewhere. */
    public boolean ends(LogRecord r) {
        if (r.kind() != RecordKind.COMMAND) {
            return false;
        }
        if (skill != null) {
            return "send_stop".equals(r.command()) && skill.equals(skillOf(r.to()));
        }
        return argument != null && sameCommand(r) && !argument.equals(firstArgument(r.arguments()));
    }

    private boolean sameCommand(LogRecord r) {
        // A record of the older format has no protocol: it matches by command, as the rules do.
        return command.equals(r.command()) && (protocol == null || r.protocol().isEmpty()
                || protocol.equals(r.protocol()));
    }

    /** In a few words: {@code skill GoToChargingStation}, {@code goTo charging_station}. */
    public String describe() {
        return skill != null ? "skill " + skill : command + (argument == null ? "" : " " + argument);
    }

    /** A skill's name from its port: {@code /GoToDestination/BT_rpc/server} is {@code GoToDestination}. */
    public static String skillOf(String port) {
        String p = port.startsWith("/") ? port.substring(1) : port;
        int slash = p.indexOf('/');
        return slash < 0 ? p : p.substring(0, slash);
    }

    private static String firstArgument(String arguments) {
        String a = arguments.strip();
        int space = a.indexOf(' ');
        return space < 0 ? a : a.substring(0, space);
    }
}
