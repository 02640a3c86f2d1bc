package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.util.concurrent.Callable;

/**
 * {@code predmon abstraction list|show NAME|check FILE LOGS...}: the built-in abstractions, to use by name or to start
 * one's own from, and a check of a file's properties against logs.
 */
@Command(name = "abstraction", mixinStandardHelpOptions = true,
        description = "The built-in abstractions: 'list' names them, 'show NAME' prints one as JSON (save it, edit it, "
                + "and pass the file to --abstraction); 'check FILE LOGS...' names every name of its properties that "
                + "no record of the logs holds.",
        subcommands = {AbstractionCommand.List.class, AbstractionCommand.Show.class, AbstractionCheckCommand.class})
final class AbstractionCommand implements Runnable {

    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }

    /** {@code abstraction list}. */
    @Command(name = "list", mixinStandardHelpOptions = true, description = "Name each built-in abstraction.")
    static final class List implements Callable<Integer> {

        @Spec
        CommandSpec spec;

        @Override
        public Integer call() {
            PrintWriter out = spec.commandLine().getOut();
            for (String name : AbstractionFiles.BUILTIN_NAMES) {
                Abstraction a = AbstractionFiles.builtin(name).orElseThrow();
                out.println(name + "\t" + a.inputAlphabet().size() + " inputs, " + a.outputAlphabet().size()
                        + " outputs, locations " + a.locations().keySet().stream().sorted().toList()
                        + (a.topicRules().isEmpty() ? "" : ", ROS 2 topics " + a.topicRules().stream()
                                .map(dev.predmon.ros2.TopicRule::topic).distinct().toList()));
            }
            out.flush();
            return ExitCodes.OK;
        }
    }

    /** {@code abstraction show NAME}. */
    @Command(name = "show", mixinStandardHelpOptions = true, description = "Print a built-in abstraction as JSON.")
    static final class Show implements Callable<Integer> {

        @Spec
        CommandSpec spec;

        @Parameters(paramLabel = "NAME", description = "thesis, scope-fetch or nav2")
        String name;

        @Override
        public Integer call() throws BadInputException {
            String json = AbstractionFiles.builtinJson(name).orElseThrow(() -> new BadInputException(
                    "'" + name + "': not a built-in abstraction (one of " + String.join(", ", AbstractionFiles.BUILTIN_NAMES) + ")"));
            PrintWriter out = spec.commandLine().getOut();
            out.print(json);
            out.flush();
            return ExitCodes.OK;
        }
    }
}
