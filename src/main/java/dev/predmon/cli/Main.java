package dev.predmon.cli;

import picocli.CommandLine;

/** Entry point of {@code predmon.jar}. */
public final class Main {

    private Main() {
    }

    public static void main(String[] args) {
        System.exit(commandLine().execute(args));
    }

    /** The configured command line: used by {@link #main} and by in-process tests. */
    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new PredmonCommand());
        cl.setExecutionExceptionHandler(new ErrorHandler());
        cl.setUsageHelpAutoWidth(true);
        return cl;
    }
}
