package dev.predmon.simulate;

import dev.predmon.parse.RecordKind;

/**
 * One message the YARP monitor would intercept, before formatting: what {@link LogWriter} prints as one
 * seven-line record. Replies carry the canonical value ({@code 1}/{@code 0} for booleans); the writer
 * applies the print options.
 *
 * @param timeMicros log time in microseconds (relative to the logger's start, or Unix epoch)
 * @param kind       {@link RecordKind#COMMAND}, {@link RecordKind#REPLY} or {@link RecordKind#TICK}
 * @param from       sending port (for a reply, the server)
 * @param to         receiving port (for a reply, the client)
 * @param protocol   Thrift service, e.g. {@code GoTo}
 * @param command    method, e.g. {@code getStatus}
 * @param argument   first argument or {@code ""}
 * @param reply      first reply value or {@code ""}
 */
public record SimEvent(long timeMicros, RecordKind kind, String from, String to, String protocol, String command,
                       String argument, String reply) {

    /** Time in seconds, equal to what parsing the printed six-decimal time stamp gives. */
    public double time() {
        return timeMicros / 1e6;
    }

    /** The client port of the RPC this message belongs to: {@code from} for a command, {@code to} for a reply. */
    public String client() {
        return kind == RecordKind.REPLY ? to : from;
    }

    /** The server port of the RPC this message belongs to. */
    public String server() {
        return kind == RecordKind.REPLY ? from : to;
    }
}
