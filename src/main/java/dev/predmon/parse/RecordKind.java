package dev.predmon.parse;

/** The kind of an intercepted message, as the YARP monitor prints it ({@code Command intercepted:} ...). */
public enum RecordKind {
    COMMAND, REPLY, TICK, UNKNOWN
}
