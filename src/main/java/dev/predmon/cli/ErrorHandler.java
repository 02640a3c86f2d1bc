package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.Terminal;
import picocli.CommandLine;
import picocli.CommandLine.IExecutionExceptionHandler;
import picocli.CommandLine.ParseResult;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileSystemException;

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
        if (e instanceof BadInputException) {
            cl.getErr().println("predmon: " + Terminal.line(e.getMessage()));
            code = ExitCodes.BAD_INPUT;
        } else if (e instanceof IOException io) {
            cl.getErr().println("predmon: " + Terminal.line(describe(io)));
            code = ExitCodes.BAD_INPUT;
        } else {
            cl.getErr().println("predmon: internal error: " + Terminal.line(String.valueOf(e)) + (verbose ? "" : " (rerun with --verbose for details)"));
            code = ExitCodes.INTERNAL;
        }
        if (verbose) {
            e.printStackTrace(cl.getErr());
        }
        cl.getErr().flush();
        return code;
    }

    /** The file and what went wrong with it, in words (never a Java class name). */
    private static String describe(IOException e) {
        if (e instanceof FileSystemException f && f.getFile() != null) {
            return f.getFile() + ": " + BadInputException.reason(e);
        }
        return "I/O error: " + BadInputException.reason(e);
    }
}
