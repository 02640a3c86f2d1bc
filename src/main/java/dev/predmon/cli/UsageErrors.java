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
        String spelt = otherSpelling(cl, args);
        err.println("predmon: " + Terminal.line(spelt != null ? spelt : ex.getMessage()));
        if (ex.getCause() instanceof BadInputException) { // an input file named by an option cannot be read
            err.flush();
            return ExitCodes.BAD_INPUT;
        }
        if (spelt == null) { // the other spelling is the suggestion
            UnmatchedArgumentException.printSuggestions(ex, err);
        }
        err.println("see '" + cl.getCommandSpec().qualifiedName() + " --help'");
        err.flush();
        return cl.getCommandSpec().exitCodeOnInvalidInput();
    }

    /**
     * An option the command does not know but spells with or without a final {@code s} ({@code watch --logs}, as
     * {@code learn} spells it): what to write instead, or null. picocli would say first that {@code --log} is
     * missing, which hides the slip.
     */
    static String otherSpelling(CommandLine cl, String[] args) {
        for (String arg : args) {
            if (!arg.startsWith("--")) {
                continue;
            }
            String name = arg.contains("=") ? arg.substring(0, arg.indexOf('=')) : arg;
            if (cl.getCommandSpec().findOption(name) != null) {
                continue;
            }
            String other = name.endsWith("s") ? name.substring(0, name.length() - 1) : name + "s";
            if (name.length() > 3 && cl.getCommandSpec().findOption(other) != null) {
                return "unknown option '" + name + "': '" + cl.getCommandSpec().qualifiedName() + "' spells it '"
                        + other + "'";
            }
        }
        return null;
    }
}
