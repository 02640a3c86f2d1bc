package dev.predmon.parse;

/**
 * One message intercepted by the YARP monitor: a record of the log.
 *
 * <p>Fields are the monitor's, already trimmed; an empty field is {@code ""}, never {@code null}.
 * For a {@link RecordKind#REPLY} {@code from} is the server and {@code to} the client.
 *
 * @param line      1-based line number of the record's first line in its log
 * @param time      the record's time: the logger's time stamp in seconds (relative or epoch, as the log has it),
 *                  or, in a log without time stamps, the tree's tick number ({@code clock} says which)
 * @param level     the logger level, {@code DEBUG} for monitor records
 * @param kind      command, reply, tick or unknown
 * @param from      sending port
 * @param to        receiving port
 * @param protocol  Thrift service name, e.g. {@code GoTo}
 * @param command   method name, e.g. {@code getStatus}
 * @param arguments first argument (older format: all arguments, space separated)
 * @param reply     first reply value
 * @param clock     what {@code time} counts: seconds, or ticks in a log without time stamps
 */
public record LogRecord(long line, double time, String level, RecordKind kind, String from, String to,
                        String protocol, String command, String arguments, String reply, Clock clock) {

    /** A record of a log with time stamps: {@code time} is in seconds. */
    public LogRecord(long line, double time, String level, RecordKind kind, String from, String to,
                     String protocol, String command, String arguments, String reply) {
        this(line, time, level, kind, from, to, protocol, command, arguments, reply, Clock.SECONDS);
    }
}
