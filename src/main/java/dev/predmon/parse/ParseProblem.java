package dev.predmon.parse;

import java.util.Locale;

/**
 * Something the parser could not take as a record, with where it is.
 *
 * @param line     1-based line number in the log where the problem starts
 * @param severity {@code WARNING} for a log that merely ends early, {@code ERROR} for a broken record
 * @param message  what is wrong and what was expected, one line, without the file name
 */
public record ParseProblem(long line, Severity severity, String message) {

    /** How serious a problem is; errors mean a record was lost. */
    public enum Severity { WARNING, ERROR }

    /** Renders the problem as {@code file:line: severity: message}. */
    public String format(String file) {
        return file + ":" + line + ": " + severity.name().toLowerCase(Locale.ROOT) + ": " + message;
    }
}
