package dev.predmon.property;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.List;
import java.util.Locale;

/**
 * One kind of log record: each field that is given must match, the others match anything. A record without a
 * protocol (the older log format, which has no Protocol line) matches by command. Ports may use {@code *} for any
 * characters.
 *
 * @param kind      command, reply or tick, or null for any
 * @param protocol  Thrift service, e.g. {@code GoTo}, or null
 * @param command   method, e.g. {@code getStatus}, or null
 * @param from      sending port, or null
 * @param to        receiving port, or null
 * @param arguments the first argument is one of these, or null for any
 * @param replies   the first reply value is one of these, or null for any
 */
public record RecordMatch(RecordKind kind, String protocol, String command, String from, String to,
                          List<String> arguments, List<String> replies) {

    public RecordMatch {
        arguments = arguments == null ? null : List.copyOf(arguments);
        replies = replies == null ? null : List.copyOf(replies);
    }

    /** Whether {@code r} is such a record. */
    public boolean matches(LogRecord r) {
        return (kind == null || kind == r.kind())
                && (command == null || command.equals(r.command()))
                && (protocol == null || r.protocol().isEmpty() || protocol.equals(r.protocol()))
                && (from == null || Ports.matches(from, r.from()))
                && (to == null || Ports.matches(to, r.to()))
                && (arguments == null || arguments.contains(r.arguments().trim()))
                && (replies == null || replies.contains(r.reply().trim()));
    }

    /**
     * The message this matcher picks records of, whatever their argument and reply: {@code GoTo/getStatus reply} of
     * {@code GoTo/getStatus reply 3}. That the message occurs is what gives an absence of one of its values evidence.
     */
    public RecordMatch message() {
        return arguments == null && replies == null ? this : new RecordMatch(kind, protocol, command, from, to, null,
                null);
    }

    /** In a user's words: {@code GoTo/getStatus reply 3}, {@code GoTo/goTo command charging_station}. */
    public String describe() {
        StringBuilder b = new StringBuilder();
        b.append(protocol == null ? "" : protocol + "/").append(command == null ? "any message" : command);
        if (kind != null) {
            b.append(' ').append(kind.name().toLowerCase(Locale.ROOT));
        }
        if (arguments != null) {
            b.append(" (").append(String.join("|", arguments)).append(')');
        }
        if (replies != null) {
            b.append(kind == RecordKind.REPLY ? " " : " reply ").append(String.join("|", replies));
        }
        if (from != null) {
            b.append(" from ").append(from);
        }
        if (to != null) {
            b.append(" to ").append(to);
        }
        return b.toString();
    }

    /**
     * In an operator's words, without kinds and ports: {@code hasGrasped 1 or 27503}, {@code goTo charging_station},
     * {@code halt}.
     */
    public String brief() {
        StringBuilder b = new StringBuilder(command != null ? command : protocol != null ? protocol : "any message");
        if (arguments != null) {
            b.append(' ').append(String.join(" or ", arguments));
        }
        if (replies != null) {
            b.append(' ').append(String.join(" or ", replies));
        }
        return b.toString();
    }

    /** Port patterns: {@code *} for any characters, anything else literally. */
    private static final class Ports {
        private Ports() {
        }

        static boolean matches(String pattern, String port) {
            int star = pattern.indexOf('*');
            if (star < 0) {
                return pattern.equals(port);
            }
            return glob(pattern, 0, port, 0);
        }

        private static boolean glob(String p, int i, String s, int j) {
            while (i < p.length()) {
                char c = p.charAt(i);
                if (c == '*') {
                    for (int k = j; k <= s.length(); k++) {
                        if (glob(p, i + 1, s, k)) {
                            return true;
                        }
                    }
                    return false;
                }
                if (j >= s.length() || s.charAt(j) != c) {
                    return false;
                }
                i++;
                j++;
            }
            return j == s.length();
        }
    }
}
