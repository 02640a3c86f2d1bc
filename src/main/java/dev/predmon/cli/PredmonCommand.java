package dev.predmon.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ScopeType;
import picocli.CommandLine.Spec;

/** The top command: lists the subcommands. */
@Command(name = "predmon", mixinStandardHelpOptions = true, version = "predmon 0.1.0",
        description = "Predictive runtime monitoring of robots: learns one Mealy machine per scenario from YARP "
                + "monitor logs and warns while a robot runs as soon as the run can only be a faulty scenario.",
        subcommands = {LearnCommand.class, VerifyCommand.class, ClassifyCommand.class, WatchCommand.class,
                SimulateCommand.class, EvaluateCommand.class, ExplainCommand.class,
                ExportSamplesCommand.class, BenchCommand.class, DemoCommand.class, AbstractionCommand.class},
        footer = {"", "Exit codes: 0 ok / no warning, 1 warning raised (verify: mismatch), 2 usage, 3 bad input, "
                + "4 internal error."})
public final class PredmonCommand implements Runnable {

    @Spec
    CommandSpec spec;

    /** Read by {@link ErrorHandler}: print stack traces. */
    @Option(names = "--verbose", scope = ScopeType.INHERIT, description = "Print stack traces of errors.")
    boolean verbose;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }
}
