package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.AbstractionException;
import picocli.CommandLine;
import picocli.CommandLine.IExecutionExceptionHandler;
import picocli.CommandLine.ParseResult;

import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * The one place where failures become a message and an exit code: known bad input is one line naming the
 * file and what is wrong (exit {@value ExitCodes#BAD_INPUT}); anything else is a bug (exit
 * {@value ExitCodes#INTERNAL}). {@code --verbose} adds the stack trace.
 */
final class ErrorHandler implements IExecutionExceptionHandler {

    @Override
    public int handleExecutionException(Exception ex, CommandLine cl, ParseResult parsed) {
        boolean verbose = parsed.hasMatchedOption("--verbose")
                || (parsed.subcommand() != null && parsed.subcommand().hasMatchedOption("--verbose"));
        Throwable e = ex instanceof UncheckedIOException u ? u.getCause() : ex;
        int code;
        if (e instanceof BadInputException || e instanceof AbstractionException) {
            cl.getErr().println("predmon: " + e.getMessage());
            code = ExitCodes.BAD_INPUT;
        } else if (e instanceof IOException) {
            cl.getErr().println("predmon: " + describe(e));
            code = ExitCodes.BAD_INPUT;
        } else {
            cl.getErr().println("predmon: internal error: " + e + (verbose ? "" : " (rerun with --verbose for details)"));
            code = ExitCodes.INTERNAL;
        }
        if (verbose) {
            e.printStackTrace(cl.getErr());
        }
        cl.getErr().flush();
        return code;
    }

    private static String describe(Throwable e) {
        if (e instanceof java.nio.file.NoSuchFileException n) {
            return n.getFile() + ": no such file";
        }
        if (e instanceof java.nio.file.AccessDeniedException a) {
            return a.getFile() + ": permission denied";
        }
        return "I/O error: " + e.getMessage();
    }
}
