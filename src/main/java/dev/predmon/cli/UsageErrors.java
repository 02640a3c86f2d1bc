package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.Terminal;
import picocli.CommandLine;
import picocli.CommandLine.IParameterExceptionHandler;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.UnmatchedArgumentException;

import java.io.PrintWriter;

/**
 * A usage error (unknown option, missing or impossible value) is its one line, picocli's "Did you mean" suggestion
 * when it has one, and where the help is: {@code see 'predmon watch --help'}. The whole help (30 to 65 lines) used
 * to follow the line and scroll it out of sight. Exit {@value ExitCodes#USAGE}; {@value ExitCodes#BAD_INPUT} where an
 * input file an option names cannot be read ({@code --config}).
 */
final class UsageErrors implements IParameterExceptionHandler {

    @Override
    public int handleParseException(ParameterException ex, String[] args) {
        CommandLine cl = ex.getCommandLine();
        PrintWriter err = cl.getErr();
        err.println("predmon: " + Terminal.line(ex.getMessage()));
        if (ex.getCause() instanceof BadInputException) { // an input file named by an option cannot be read
            err.flush();
            return ExitCodes.BAD_INPUT;
        }
        UnmatchedArgumentException.printSuggestions(ex, err);
        err.println("see '" + cl.getCommandSpec().qualifiedName() + " --help'");
        err.flush();
        return cl.getCommandSpec().exitCodeOnInvalidInput();
    }
}
