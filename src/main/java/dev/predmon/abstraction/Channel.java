package dev.predmon.abstraction;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.util.Objects;

/**
 * The RPC connection a message travels on, seen from the client. A command and its reply have the same
 * channel: the reply's ports are swapped back.
 *
 * <p>A value class like a record, but with its hash computed once: the compactor and the hysteresis look every
 * interface message's channel up in a map, and a record's hash combined its four strings on every look-up (a tenth
 * of the pipeline's time on a large log). The abstraction hands out one instance per connection, so equality is
 * usually decided by identity.
 */
public final class Channel {
    private final String client;
    private final String server;
    private final String protocol;
    private final String command;
    private final int hash;

    public Channel(String client, String server, String protocol, String command) {
        this.client = Objects.requireNonNull(client, "client");
        this.server = Objects.requireNonNull(server, "server");
        this.protocol = Objects.requireNonNull(protocol, "protocol");
        this.command = Objects.requireNonNull(command, "command");
        this.hash = ((client.hashCode() * 31 + server.hashCode()) * 31 + protocol.hashCode()) * 31 + command.hashCode();
    }

    /** The channel of a command or reply record. */
    public static Channel of(LogRecord r) {
        return r.kind() == RecordKind.REPLY
                ? new Channel(r.to(), r.from(), r.protocol(), r.command())
                : new Channel(r.from(), r.to(), r.protocol(), r.command());
    }

    public String client() {
        return client;
    }

    public String server() {
        return server;
    }

    public String protocol() {
        return protocol;
    }

    public String command() {
        return command;
    }

    @Override
    public boolean equals(Object o) {
        return o == this || (o instanceof Channel c && c.hash == hash && c.client.equals(client)
                && c.server.equals(server) && c.protocol.equals(protocol) && c.command.equals(command));
    }

    @Override
    public int hashCode() {
        return hash;
    }

    @Override
    public String toString() {
        return "Channel[client=" + client + ", server=" + server + ", protocol=" + protocol + ", command=" + command + "]";
    }
}
