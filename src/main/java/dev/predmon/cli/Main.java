package dev.predmon.cli;

import picocli.CommandLine;

import java.util.List;

/** Entry point of {@code predmon.jar}. */
public final class Main {

    private Main() {
    }

    public static void main(String[] args) {
        // A Java Error (out of memory, a stack overflow) is no Exception, so picocli passes it by the error handler:
        // on the main thread it would end the JVM with a stack trace and exit 1, the code of a warning; on another
        // thread (a follower, the live server) it would end that thread alone and leave the command half alive.
        FatalErrors fatal = new FatalErrors(System.err, List.of(args).contains("--verbose"));
        Thread.setDefaultUncaughtExceptionHandler(fatal);
        Stdout out = Stdout.open();
        CommandLine cl = commandLine(args);
        cl.setOut(out);
        int code;
        try {
            code = out.settle(cl.execute(args), cl.getErr());
        } catch (Error e) {
            code = fatal.report(e);
        }
        System.exit(code);
    }

    /** The configured command line with every subcommand: used by in-process tests. */
    public static CommandLine commandLine() {
        return configure(PredmonCommand.SUBCOMMANDS);
    }

    /**
     * The command line that runs {@code args}. When the first argument is exactly a subcommand's name, only that
     * subcommand is added: building the other ten (picocli reflects over each command, its mixins and option types)
     * took a third of a second of every start. Anything else (no arguments, {@code --help}, {@code --version}, a
     * top-level option, an unknown or misspelt name) gets the full command line, so that usage, "Did you mean"
     * suggestions and errors list every subcommand. Within a subcommand picocli looks only at that subcommand, so
     * its help, errors and behaviour are the same either way.
     */
    static CommandLine commandLine(String[] args) {
        return configure(args.length == 0 ? PredmonCommand.SUBCOMMANDS
                : PredmonCommand.subcommand(args[0]).<List<Class<?>>>map(List::of).orElse(PredmonCommand.SUBCOMMANDS));
    }

    private static CommandLine configure(List<Class<?>> subcommands) {
        CommandLine cl = new CommandLine(new PredmonCommand());
        for (Class<?> subcommand : subcommands) {
            cl.addSubcommand(subcommand);
        }
        // after the subcommands: both settings are passed down to the subcommands present when they are set
        cl.setExecutionExceptionHandler(new ErrorHandler());
        cl.setParameterExceptionHandler(new UsageErrors());
        cl.setUsageHelpAutoWidth(true);
        return cl;
    }
}
