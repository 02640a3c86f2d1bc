package dev.predmon.rosbag;

/** CDR bytes that do not hold a message of the expected type; the message says where and what was expected. */
final class CdrException extends Exception {
    private static final long serialVersionUID = 1L;

    CdrException(String message) {
        super(message);
    }
}
