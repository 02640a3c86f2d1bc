package dev.predmon;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Bad external input (a log, a log directory, a model directory, an abstraction or scenario file): the message is
 * one line that says what is wrong and where ({@code file:line} when there is a line), ready to show to a user.
 * It is the root of predmon's checked exceptions for bad input (the abstraction loader's
 * {@code AbstractionException} is one), so the command line turns every one of them into exit 3 the same way.
 */
public class BadInputException extends Exception {
    public BadInputException(String message) {
        super(message);
    }

    public BadInputException(String message, Throwable cause) {
        super(message, cause);
    }

    /** {@code file: cannot read: reason}, the reason in words ({@link #reason}), never a Java class name. */
    public static BadInputException cannotRead(Path file, IOException e) {
        return new BadInputException(file + ": cannot read: " + reason(e), e);
    }

    /**
     * What went wrong with a file, in words: {@code no such file}, {@code permission denied}, {@code is a directory}
     * (the operating system's reason, lower-cased), never a Java class name and never the file name (callers put
     * it first).
     */
    public static String reason(IOException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NotDirectoryException) {
            return "not a directory";
        }
        if (e instanceof DirectoryNotEmptyException) {
            return "directory not empty";
        }
        if (e instanceof FileAlreadyExistsException) {
            return "already exists";
        }
        String r = e instanceof FileSystemException f ? f.getReason() : e.getMessage();
        r = r == null ? "" : r.strip().lines().findFirst().orElse("");
        return r.isEmpty() ? "I/O error" : r.substring(0, 1).toLowerCase(Locale.ROOT) + r.substring(1);
    }
}
