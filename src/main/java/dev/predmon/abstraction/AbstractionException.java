package dev.predmon.abstraction;

import dev.predmon.BadInputException;

/** A bad abstraction file; the message names the file, the position and the reason. */
public final class AbstractionException extends BadInputException {
    public AbstractionException(String message) {
        super(message);
    }

    public AbstractionException(String message, Throwable cause) {
        super(message, cause);
    }
}
