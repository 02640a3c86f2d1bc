package dev.predmon.abstraction;

/** A bad abstraction file; the message names the file, the position and the reason. */
public final class AbstractionException extends Exception {
    public AbstractionException(String message) {
        super(message);
    }

    public AbstractionException(String message, Throwable cause) {
        super(message, cause);
    }
}
