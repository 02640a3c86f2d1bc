package dev.predmon.abstraction;

/**
 * A kind of interface message that no rule of the abstraction maps, as the abstraction found it: the command it is of,
 * why it is not mapped, and the value that tells it apart (a reply no rule takes, a location the abstraction does not
 * know). Counted by kind ({@code pipeline.UnmappedCounts}); {@link #text()} is its one written form, for people and
 * for JSON.
 *
 * @param protocol the Thrift service, empty in the older log format (which has none)
 * @param command  the method
 * @param kind     why it is not mapped
 * @param detail   the reply value ({@link Kind#REPLY}) or the location ({@link Kind#COMMAND_LOCATION},
 *                 {@link Kind#REPLY_LOCATION}); empty for the other kinds
 */
public record UnmappedMessage(String protocol, String command, Kind kind, String detail)
        implements Comparable<UnmappedMessage> {

    /** Why a message is not mapped. */
    public enum Kind {
        /** A command of a command no rule takes. */
        COMMAND,
        /** A reply no rule takes: of a command without a rule, or a value none of its rule's replies takes. */
        REPLY,
        /** A command about a location the abstraction does not know. */
        COMMAND_LOCATION,
        /** A reply about a location the abstraction does not know. */
        REPLY_LOCATION,
        /** Every kind of the command beyond those counted apart, counted together. */
        OTHER_VALUES,
        /** Every kind of every command beyond those counted apart, counted together. */
        OTHER_COMMANDS
    }

    /** The text of {@link Kind#OTHER_VALUES}, after its command. */
    public static final String OTHER = "(other values)";
    /** Every message beyond both bounds of the counts. */
    public static final UnmappedMessage OTHER_COMMANDS = new UnmappedMessage("", "", Kind.OTHER_COMMANDS, "");

    public UnmappedMessage {
        detail = detail == null ? "" : detail;
    }

    /** What stands for every kind of {@code m}'s command beyond those counted apart. */
    public static UnmappedMessage otherValues(UnmappedMessage m) {
        return new UnmappedMessage(m.protocol, m.command, Kind.OTHER_VALUES, "");
    }

    /** {@code Protocol/command}, as users name a message ({@code command} alone without a protocol). */
    public String name() {
        return protocol.isEmpty() ? command : protocol + "/" + command;
    }

    /** The location the abstraction does not know, or null when the message names none. */
    public String location() {
        return kind == Kind.COMMAND_LOCATION || kind == Kind.REPLY_LOCATION ? detail : null;
    }

    /**
     * How users and JSON read it: {@code GoTo/teleport command}, {@code GoTo/getStatus reply '7'},
     * {@code GoTo/goTo command about unknown location 'bedroom'}, {@code GoTo/getCurrentPose (other values)},
     * {@code (other commands)}.
     */
    public String text() {
        return switch (kind) {
            case COMMAND -> name() + " command";
            case REPLY -> name() + " reply '" + detail + "'";
            case COMMAND_LOCATION -> name() + " command about unknown location '" + detail + "'";
            case REPLY_LOCATION -> name() + " reply about unknown location '" + detail + "'";
            case OTHER_VALUES -> name() + " " + OTHER;
            case OTHER_COMMANDS -> "(other commands)";
        };
    }

    /** In the order of their texts. */
    @Override
    public int compareTo(UnmappedMessage o) {
        return text().compareTo(o.text());
    }

    @Override
    public String toString() {
        return text();
    }
}
