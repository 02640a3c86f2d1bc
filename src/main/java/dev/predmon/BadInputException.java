package dev.predmon;

/**
 * Bad external input (a log directory, a model directory, a scenario file): the message is one line that
 * says what is wrong and where ({@code file:line} when there is a line), ready to show to a user.
 */
public class BadInputException extends Exception {
    public BadInputException(String message) {
        super(message);
    }

    public BadInputException(String message, Throwable cause) {
        super(message, cause);
    }
}
