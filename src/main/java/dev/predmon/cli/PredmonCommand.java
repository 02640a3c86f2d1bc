package dev.predmon.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ScopeType;
import picocli.CommandLine.Spec;

import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;

/**
 * The top command. Its subcommands are {@link #SUBCOMMANDS}, added by {@link Main} rather than listed in the
 * annotation, so that a run of one subcommand need not build the other ten (picocli reflects over every command
 * class, its mixins and option types when it builds a command line).
 */
@Command(name = "predmon", mixinStandardHelpOptions = true, version = "predmon 0.1.0",
        description = "Predictive runtime monitoring of robots: learns one Mealy machine per scenario from YARP "
                + "monitor logs, and the odds of a violation from each state; while a robot runs it forecasts the "
                + "violation of the safety property and warns before it.",
        footer = {"", "Exit codes: 0 ok / no warning, 1 warning raised (verify: mismatch), 2 usage, 3 bad input, "
                + "4 internal error, 5 no model matches the run, 6 a property violated with no warning before it."})
public final class PredmonCommand implements Callable<Integer> {

    /**
     * The subcommands, in the order usage lists them: the one list of them. Their names are those of their own
     * {@code @Command} annotations.
     */
    static final List<Class<?>> SUBCOMMANDS = List.of(LearnCommand.class, VerifyCommand.class, ClassifyCommand.class,
            WatchCommand.class, SimulateCommand.class, EvaluateCommand.class, ExplainCommand.class,
            ExportSamplesCommand.class, BenchCommand.class, DemoCommand.class, AbstractionCommand.class);

    @Spec
    CommandSpec spec;

    /** Read by {@link ErrorHandler}: print stack traces. */
    @Option(names = "--verbose", scope = ScopeType.INHERIT, description = "Print stack traces of errors.")
    boolean verbose;

    /**
     * The subcommand called exactly {@code name} (or one of its aliases), if there is one. Reads only the classes'
     * {@code @Command} annotations: it neither instantiates nor initialises a command.
     */
    static Optional<Class<?>> subcommand(String name) {
        for (Class<?> c : SUBCOMMANDS) {
            Command command = c.getAnnotation(Command.class);
            if (command.name().equals(name) || Arrays.asList(command.aliases()).contains(name)) {
                return Optional.of(c);
            }
        }
        return Optional.empty();
    }

    /** {@code predmon} without a subcommand: a usage error, so the usage goes to stderr with exit 2. */
    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getErr());
        return ExitCodes.USAGE;
    }
}
