package dev.predmon.abstraction;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

/**
 * The RPC connection a message travels on, seen from the client. A command and its reply have the same
 * channel: the reply's ports are swapped back.
 */
public record Channel(String client, String server, String protocol, String command) {

    /** The channel of a command or reply record. */
    public static Channel of(LogRecord r) {
        return r.kind() == RecordKind.REPLY
                ? new Channel(r.to(), r.from(), r.protocol(), r.command())
                : new Channel(r.from(), r.to(), r.protocol(), r.command());
    }
}
